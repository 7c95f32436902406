// apps/tessera/cmd_studio.cpp — `tessera studio [--port P] [--open] [--root DIR]`: runs the
// studio HTTP server (apps/studio/, docs/studio.md) until Ctrl-C or SIGTERM, which stop it
// gracefully: running jobs are cancelled, every thread joined.
#include <pthread.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include "apps/studio/server.hpp"
#include "apps/studio/static_files.hpp"
#include "common.hpp"

#ifndef TESSERA_STUDIO_SOURCE_APP_DIR
#define TESSERA_STUDIO_SOURCE_APP_DIR ""
#endif

extern char** environ;

namespace tessera_cli {
namespace {

namespace fs = std::filesystem;

struct StudioArgs {
    tessera_studio::StudioConfig config;
    std::string root = ".", app_dir;
    unsigned long long max_body = 8ull << 20;
    bool open = false;
    bool quiet = false;
};

// SIGINT and SIGTERM, blocked in every thread started after construction (the server's
// workers and jobs inherit the mask) and awaited by a thread of its own, which runs
// `on_signal` once. A later signal, 0.2 s or more after the first (`timeout -s INT` and
// process-group kills deliver one interrupt twice), ends the process the default way.
class SignalStop {
public:
    explicit SignalStop(std::function<void()> on_signal) {
        sigemptyset(&set_);
        for (int s : {SIGINT, SIGTERM, SIGUSR1}) sigaddset(&set_, s);
        pthread_sigmask(SIG_BLOCK, &set_, &previous_);
        thread_ = std::thread([this, on_signal = std::move(on_signal)] { wait(on_signal); });
    }
    ~SignalStop() {
        pthread_kill(thread_.native_handle(), SIGUSR1);  // wakes the waiting thread if no signal came
        thread_.join();
        pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
    }
    SignalStop(const SignalStop&) = delete;
    SignalStop& operator=(const SignalStop&) = delete;

private:
    void wait(const std::function<void()>& on_signal) {
        int signal = 0;
        if (sigwait(&set_, &signal) != 0 || signal == SIGUSR1) return;
        const timespec duplicate_window{0, 200'000'000};
        sigset_t stop_signals;
        sigemptyset(&stop_signals);
        sigaddset(&stop_signals, SIGINT);
        sigaddset(&stop_signals, SIGTERM);
        sigtimedwait(&stop_signals, nullptr, &duplicate_window);  // swallows a duplicate
        std::signal(SIGINT, SIG_DFL);
        std::signal(SIGTERM, SIG_DFL);
        pthread_sigmask(SIG_UNBLOCK, &stop_signals, nullptr);  // a second Ctrl-C kills
        on_signal();
        int last = 0;
        sigset_t wake;
        sigemptyset(&wake);
        sigaddset(&wake, SIGUSR1);
        sigwait(&wake, &last);
    }

    sigset_t set_{}, previous_{};
    std::thread thread_;
};

bool on_path(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    const std::string dirs = path;
    for (size_t start = 0; start <= dirs.size();) {
        const size_t colon = std::min(dirs.find(':', start), dirs.size());
        const fs::path candidate = fs::path(dirs.substr(start, colon - start)) / program;
        if (::access(candidate.c_str(), X_OK) == 0) return true;
        start = colon + 1;
    }
    return false;
}

// xdg-open in the background, through a shell that returns at once (xdg-open may wait for
// the browser), without the server's sockets and with the default signal mask.
void open_browser(const std::string& url) {
    if (!on_path("xdg-open")) {
        std::cerr << "tessera studio: could not open a browser (xdg-open not found); open " << url
                  << std::endl;
        return;
    }
    posix_spawn_file_actions_t files;
    posix_spawnattr_t attributes;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addclosefrom_np(&files, 3);
    posix_spawnattr_init(&attributes);
    sigset_t none;
    sigemptyset(&none);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
    const char* argv[] = {"sh", "-c", "xdg-open \"$1\" >/dev/null 2>&1 &", "sh", url.c_str(), nullptr};
    pid_t pid = 0;
    const int error = posix_spawnp(&pid, "sh", &files, &attributes, const_cast<char* const*>(argv), environ);
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attributes);
    int status = 0;
    if (error != 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        std::cerr << "tessera studio: could not open a browser; open " << url << std::endl;
}

fs::path executable_path() {
    std::error_code error;
    return fs::read_symlink("/proc/self/exe", error);
}

void run_studio(StudioArgs& args) {
    tessera_studio::StudioConfig& config = args.config;
    config.root = args.root;
    config.app_dir = args.app_dir.empty()
                         ? tessera_studio::default_app_dir(executable_path(), TESSERA_STUDIO_SOURCE_APP_DIR)
                         : fs::path(args.app_dir);
    config.max_body = static_cast<std::size_t>(args.max_body);
    if (config.port < 0 || config.port > 65535)
        fail_option("--port must be 0 to 65535, got " + std::to_string(config.port));
    if (args.max_body == 0) fail_option("--max-body must be > 0");
    std::optional<tessera_studio::StudioServer> server;
    std::atomic<tessera_studio::StudioServer*> running{nullptr};
    std::atomic<bool> signalled{false};
    SignalStop signal_stop([&] {
        signalled = true;
        if (auto* s = running.load()) s->stop();
    });
    server.emplace(config);  // after SignalStop: its threads inherit the blocked signals
    running = &*server;
    if (signalled) server->stop();  // a signal that came while it was being made
    server->bind();
    std::cout << "tessera studio: " << server->url() << std::endl;  // first line: scripts read the port here
    if (!args.quiet) {
        if (config.host != "127.0.0.1" && config.host != "localhost" && config.host != "::1")
            std::cerr
                << "tessera studio: warning: listening on " << config.host
                << ": anyone who can reach it can drive the server and read the example files under the root"
                << std::endl;
        std::cerr << "tessera studio: root " << fs::canonical(config.root).string() << ", front end "
                  << (config.app_dir.empty() ? "not built (built-in page)" : config.app_dir.string())
                  << "; Ctrl-C stops" << std::endl;
    }
    if (args.open) open_browser(server->url());
    server->serve();
    if (!args.quiet) std::cerr << "tessera studio: stopped" << std::endl;
}

}  // namespace

Subcommand add_studio_command(CLI::App& app) {
    auto args = std::make_shared<StudioArgs>();
    CLI::App* cmd = app.add_subcommand(
        "studio",
        "Run the studio: a local HTTP server for painting element fields in a browser (brushing, "
        "docs/brush.md) and its API (docs/studio.md). Runs until Ctrl-C.");
    add_integer_option(
        *cmd, "--port", args->config.port,
        "Port to listen on; 0 = any free port. The URL is printed as the first line of stdout.")
        ->type_name("P");
    cmd->add_option(
           "--host", args->config.host,
           "Address to listen on. Anything but a loopback address lets every machine that reaches it "
           "drive the server and read the example files under --root.")
        ->capture_default_str()
        ->type_name("ADDRESS");
    cmd->add_flag("--open", args->open, "Open the studio in a browser (xdg-open).");
    cmd->add_option("--root", args->root,
                    "Project root whose example files (.json, .csv, .obj, .ply, .png) may be read.")
        ->capture_default_str()
        ->type_name("DIR");
    cmd->add_option("--app-dir", args->app_dir,
                    "Folder of the web front end; default: share/tessera/studio next to the executable, else "
                    "web/dist of the source tree, else a built-in page.")
        ->type_name("DIR");
    add_integer_option(*cmd, "--max-body", args->max_body,
                       "Largest request body accepted, in bytes (larger: 413).")
        ->type_name("BYTES");
    add_integer_option(*cmd, "--threads", args->config.http_threads, "HTTP worker threads (at least 2).")
        ->type_name("N");
    add_integer_option(*cmd, "--max-jobs", args->config.max_jobs,
                       "Operations running at once over all sessions (more: 503).")
        ->type_name("N");
    add_quiet_option(*cmd, args->quiet);
    return {cmd, [args] { run_studio(*args); }};
}

}  // namespace tessera_cli
