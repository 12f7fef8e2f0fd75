// Names of the Status values (status.hpp), for host text.
#include "driftlab/proto/status.hpp"

namespace driftlab {
namespace proto {

const char* status_name(Status status) {
  switch (status) {
  case Status::ok: return "ok";
  case Status::bad_length: return "bad_length";
  case Status::unknown_type: return "unknown_type";
  case Status::out_of_range: return "out_of_range";
  case Status::bad_version: return "bad_version";
  case Status::not_allowed: return "not_allowed";
  case Status::busy: return "busy";
  case Status::not_stored: return "not_stored";
  case Status::unauthenticated: return "unauthenticated";
  case Status::replayed: return "replayed";
  }
  return nullptr;
}

}  // namespace proto
}  // namespace driftlab
