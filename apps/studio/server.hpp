// apps/studio/server.hpp — the studio HTTP server (docs/studio.md): a local server over
// tessera::BrushCanvas sessions for the web front end in web/, run by `tessera studio` and
// started in-process by the tests. It serves the app folder's static files, read-only
// example files under the project root, and the JSON API of sessions, palettes, operations
// and jobs. Everything it holds lives in the server object: no global mutable state.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>

namespace tessera_studio {

struct StudioConfig {
    // Loopback by default: anything that can reach the port can drive the server and read
    // the example files under the root (docs/studio.md, "Security").
    std::string host = "127.0.0.1";
    int port = 8420;                   // 0 = any free port (port() says which)
    std::filesystem::path root = ".";  // the project root whose example files may be read
    std::filesystem::path app_dir;     // static front end; empty = the built-in page
    std::size_t max_body = 8u << 20;   // request bodies above: 413
    int http_threads = 8;              // httplib's worker pool
    int max_jobs = 4;                  // jobs running at once; more: 503
    std::size_t max_sessions = 64;     // sessions open at once; more: 503
    std::size_t max_kept_jobs = 256;   // finished jobs still answered by GET /api/jobs/ID
};

class StudioServer {
public:
    // Checks the folders (Error(io) naming one that is not a directory).
    explicit StudioServer(StudioConfig config);
    ~StudioServer();
    StudioServer(const StudioServer&) = delete;
    StudioServer& operator=(const StudioServer&) = delete;

    // Binds the listening socket; returns the port. Error(io) when it cannot.
    int bind();
    // Serves until stop(): blocks the calling thread.
    void serve();
    // bind() and serve() on a thread of the server's own; returns once it accepts requests.
    void start();
    // Stops accepting, cancels the running jobs and joins every thread the server started.
    // Idempotent; call it from any thread but a request handler's.
    void stop();

    int port() const;
    // "http://HOST:PORT/"
    std::string url() const;

    struct State;

private:
    std::unique_ptr<State> state_;
};

}  // namespace tessera_studio
