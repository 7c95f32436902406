// Names of error kinds, for messages and exit-code tables.
#include "tessera/error.hpp"

namespace tessera {

const char* to_string(ErrorKind kind) {
    switch (kind) {
        case ErrorKind::input: return "input";
        case ErrorKind::domain: return "domain";
        case ErrorKind::option: return "option";
        case ErrorKind::io: return "io";
        case ErrorKind::internal: return "internal";
        case ErrorKind::cancelled: return "cancelled";
    }
    return "unknown";
}

}  // namespace tessera
