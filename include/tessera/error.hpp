// tessera/error.hpp — the one exception type the library throws, with a kind,
// so that the CLI can map kinds to exit codes and Python to exception classes.
// Messages are one line and name the file, line or parameter at fault.
#pragma once

#include <stdexcept>
#include <string>

namespace tessera {

enum class ErrorKind {
    input,     // malformed or invalid exemplar / data file content
    domain,    // an invalid output domain (empty, zero or negative size)
    option,    // an invalid option value (radius <= 0, iterations < 0, ...)
    io,        // a file could not be read or written
    internal,  // a broken invariant inside tessera: a bug
    cancelled  // the progress callback asked to stop
};

const char* to_string(ErrorKind kind);

class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
    ErrorKind kind() const { return kind_; }

private:
    ErrorKind kind_;
};

// Thrown when the progress callback returns false; the run leaves no output.
class Cancelled : public Error {
public:
    Cancelled() : Error(ErrorKind::cancelled, "cancelled by the progress callback") {}
};

}  // namespace tessera
