// The canonical log of a host-in-the-loop run (`driftlab hil`): one row per record the host end completes, opened
// once the handshake has produced VERSION and CONFIG for its metadata.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "driftlab/proto/messages.hpp"
#include "driftlab/receiver/row_assembler.hpp"
#include "host/io/log_assembler.hpp"
#include "host/log/log_writer.hpp"

namespace driftlab::host::io {

class HilLog {
public:
    /// `extra`: the run's own metadata (seed, model, preset...) beside the board's.
    HilLog(std::string path, CaptureHeader extra) : path_(std::move(path)), extra_(std::move(extra)) {}

    void open(const proto::VersionPayload& v, const proto::ConfigPayload& c);
    void write(const receiver::Row& r);
    void close();

private:
    std::string path_;
    CaptureHeader extra_;
    bool raw_ = false;
    std::unique_ptr<LogWriter> writer_;
};

}  // namespace driftlab::host::io
