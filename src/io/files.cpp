// io/files.cpp — the file-system side of io: load() by extension (in the file, type
// mesh paths are relative to the JSON file), whole-file reads, and atomic writes
// (temporary file in the target directory + rename), so that a failed or interrupted
// run never leaves a partial output behind (DESIGN.md, "Formats"). save() is in
// save.cpp; parsing and serialising live in the *_format.cpp files.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>

#include "io/io_util.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"

namespace tessera {

using namespace io_detail;

namespace {

[[noreturn]] void fail_io(const std::string& what, const std::string& path, int error_number) {
    throw Error(ErrorKind::io, "cannot " + what + " " + path + ": " + std::strerror(error_number));
}

// A name no other writer uses at the same time: the pid separates processes, the
// thread id separates threads of one process writing the same path.
std::string temporary_name(const std::string& path) {
    const size_t thread_hash = std::hash<std::thread::id>{}(std::this_thread::get_id());
    return path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(thread_hash);
}

// Writes all of `content` to a new file and flushes it to disk; returns errno or 0.
int write_whole_file(const std::string& file_name, const std::string& content) {
    std::FILE* file = std::fopen(file_name.c_str(), "wb");
    if (!file) return errno;
    int error_number = 0;
    if (!content.empty() && std::fwrite(content.data(), 1, content.size(), file) != content.size())
        error_number = errno ? errno : EIO;
    // fsync before rename: otherwise a crash can leave the new name pointing at an empty file.
    if (!error_number && (std::fflush(file) != 0 || ::fsync(::fileno(file)) != 0)) error_number = errno;
    if (std::fclose(file) != 0 && !error_number) error_number = errno;
    return error_number;
}

}  // namespace

void write_file_atomic(const std::string& path, const std::string& content) {
    if (path.empty()) throw Error(ErrorKind::io, "cannot write a file with an empty name");
    const std::string temporary = temporary_name(path);
    errno = 0;
    const int error_number = write_whole_file(temporary, content);
    if (error_number != 0) {
        std::remove(temporary.c_str());
        fail_io("write", path, error_number);
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const int rename_error = errno;
        std::remove(temporary.c_str());
        fail_io("write", path, rename_error);
    }
}

std::string read_file(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) fail_io("read", path, errno);
    std::string content;
    char buffer[1 << 16];
    size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) content.append(buffer, n);
    // A directory opens fine on Linux and fails here with EISDIR.
    const bool failed = std::ferror(file) != 0;
    const int error_number = errno;
    std::fclose(file);
    if (failed) fail_io("read", path, error_number ? error_number : EIO);
    return content;
}

Exemplar load(const std::string& path, const LoadOptions& options) {
    const std::string extension = load_extension(path);
    const std::string text = read_file(path);
    if (extension == ".csv") return parse_csv(text, path, options);
    Exemplar data = parse_json(text, path);
    resolve_mesh_paths(data, path);
    return data;
}

}  // namespace tessera
