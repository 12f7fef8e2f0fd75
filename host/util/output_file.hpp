// Single files a command writes (a model file, a report page): checked before the work that fills them, written
// whole at the end, so that a run neither fails only after its work nor leaves half a file behind.
#pragma once

#include <string>

namespace driftlab::host {

/// Throws DeviceError naming `path`, what it is for (`what`) and the system's reason when no file can be written
/// there (a missing folder, no permission). Leaves no file behind that was not there before.
void check_output_file(const std::string& path, const std::string& what);

/// Throws UsageError when `output` is the file `input` (by identity, so another spelling of its path or a link to
/// it too): a command must not write over what it reads, a capture above all, the only byte-for-byte record.
/// `option` names the output's option, `input_what` what the input is.
void refuse_writing_over_input(const std::string& output, const std::string& option, const std::string& input,
                               const std::string& input_what);

/// Throws UsageError when a file is already at `path` and `overwrite` is false, so that a recording is not replaced
/// by running a command once more from the shell's history. `what` names the file ("log"), `option` its option.
void refuse_replacing(const std::string& path, const std::string& what, const std::string& option, bool overwrite);

/// Throws UsageError when two outputs of one command, `path` (of `option`) and `other` (of `other_option`), are one
/// file, whether it exists yet or not: the same path once links, "." and ".." are resolved, or one file by identity.
/// The later write would replace the earlier one's file.
void refuse_two_outputs_in_one_file(const std::string& path, const std::string& option, const std::string& other,
                                    const std::string& other_option);

/// Throws UsageError when the file output `path` (of `option`) is the folder another option writes into, whether
/// it exists yet or not: the file could not be written, and only after the work that fills it.
void refuse_file_on_output_folder(const std::string& path, const std::string& option, const std::string& folder,
                                  const std::string& folder_option);

/// Writes `text` to `path` through a temporary file beside it and a rename, so that a reader never sees a part of
/// it and an earlier file stays as it was when writing fails. Throws DeviceError as above.
void write_output_file(const std::string& path, const std::string& text, const std::string& what);

}  // namespace driftlab::host
