#include "tessera/bob/status.hpp"

namespace tessera::bob {

const char* status_name(Status s) {
  switch (s) {
    case Status::kOk:
      return "ok";
    case Status::kFinished:
      return "finished";
    case Status::kBadSize:
      return "bad size";
    case Status::kBufferTooSmall:
      return "buffer too small";
    case Status::kOutOfBounds:
      return "out of bounds";
    case Status::kFrontBlocked:
      return "front blocked";
    case Status::kNotStarted:
      return "not started";
    case Status::kAlreadyStarted:
      return "already started";
  }
  return "unknown";
}

}  // namespace tessera::bob
