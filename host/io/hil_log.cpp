// The log of a host-in-the-loop run; see hil_log.hpp.
#include "host/io/hil_log.hpp"

#include "host/io/board_rows.hpp"

namespace driftlab::host::io {

void HilLog::open(const proto::VersionPayload& v, const proto::ConfigPayload& c) {
    raw_ = c.raw != 0;
    // hil's receiver leaves out a SAMPLE whose RAW was lost (MissingRaw::drop): no flags column.
    writer_ = std::make_unique<LogWriter>(path_, board_metadata("hil", v, c, extra_), board_columns(raw_, false));
}

void HilLog::write(const receiver::Row& r) { writer_->write_row(board_log_row(r, raw_, false)); }

void HilLog::close() {
    if (writer_) writer_->close();
}

}  // namespace driftlab::host::io
