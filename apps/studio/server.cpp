// apps/studio/server.cpp — the studio server's lifecycle and request intake (server.hpp):
// httplib's worker pool, every request through one intake (origin checks, the body read
// under its cap) and the route table, and a stop that cancels jobs before joining workers.
#include "apps/studio/server.hpp"

#include <arpa/inet.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <chrono>
#include <mutex>
#include <thread>

#include "apps/studio/server_context.hpp"
#include "tessera/error.hpp"

namespace tessera_studio {
namespace fs = std::filesystem;

namespace {

fs::path checked_dir(const fs::path& dir, const std::string& what) {
    std::error_code error;
    if (!fs::is_directory(dir, error))
        throw tessera::Error(tessera::ErrorKind::io, what + " " + dir.string() + " is not a directory");
    return fs::canonical(dir);
}

StudioConfig canonical(StudioConfig config) {
    config.root = checked_dir(config.root, "root folder");
    if (!config.app_dir.empty()) config.app_dir = checked_dir(config.app_dir, "app folder");
    if (config.http_threads < 2) config.http_threads = 2;
    if (config.max_jobs < 1) config.max_jobs = 1;
    return config;
}

// localhost, [::1] or an IPv4 address in 127.0.0.0/8 (as an address, so that
// "127.0.0.1.evil.example" is not one).
bool is_loopback_name(const std::string& name) {
    if (name == "localhost" || name == "::1" || name == "[::1]") return true;
    in_addr address{};
    return ::inet_pton(AF_INET, name.c_str(), &address) == 1 && (ntohl(address.s_addr) >> 24) == 127;
}

// "host:port" or "[v6]:port" -> the host name.
std::string host_name(const std::string& authority) {
    if (!authority.empty() && authority.front() == '[') return authority.substr(0, authority.find(']') + 1);
    return authority.substr(0, authority.rfind(':'));
}

// Why a request is refused before routing, or "". A server on a loopback address serves
// only pages of loopback origins: a Host header naming another host is a DNS-rebinding
// attempt, an Origin header naming another site a cross-site request.
std::string origin_problem(const httplib::Request& req, const ServerContext& ctx) {
    if (!is_loopback_name(ctx.config.host)) return "";
    const std::string host = req.get_header_value("Host");
    if (!host.empty() && !is_loopback_name(host_name(host)))
        return "Host '" + host + "' is not a loopback name; refused (DNS rebinding?)";
    const std::string origin = req.get_header_value("Origin");
    const std::string scheme = "http://";
    if (!origin.empty() &&
        (origin.rfind(scheme, 0) != 0 || !is_loopback_name(host_name(origin.substr(scheme.size())))))
        return "cross-origin request from '" + origin + "' refused";
    return "";
}

}  // namespace

ServerContext::ServerContext(StudioConfig c)
    : config(canonical(std::move(c))),
      sessions(config.max_sessions),
      jobs(config.max_jobs, config.max_kept_jobs),
      examples(config.root),
      max_streams(std::max(1, config.http_threads / 2)) {}

struct StudioServer::State {
    explicit State(StudioConfig config) : ctx(std::move(config)) {}
    void intake(const httplib::Request& req, httplib::Response& res, const httplib::ContentReader* reader);
    void setup();

    ServerContext ctx;
    Router router;
    httplib::Server http;
    std::thread thread;
    std::atomic<bool> serving{false};
    bool bound = false;
    std::mutex stop_mutex;  // stop() from two threads (a signal and a destructor) runs once at a time
};

// Every request: origin checks, then the body (read here, under the cap: httplib caps only
// bodies with a Content-Length), then the route table.
void StudioServer::State::intake(const httplib::Request& req, httplib::Response& res,
                                 const httplib::ContentReader* reader) {
    if (const std::string problem = origin_problem(req, ctx); !problem.empty()) {
        send_error(res, 403, problem);
        return;
    }
    std::string body;
    if (reader) {
        if (req.is_multipart_form_data()) {
            send_error(res, 415, "multipart bodies are not accepted; send JSON");
            return;
        }
        bool too_large = false;
        const bool read = (*reader)([&](const char* data, size_t n) {
            too_large = body.size() + n > ctx.config.max_body;
            if (!too_large) body.append(data, n);
            return !too_large;
        });
        if (!read) {
            const bool capped = too_large || res.status == 413;
            send_error(res, capped ? 413 : 400,
                       capped ? "request body larger than " + std::to_string(ctx.config.max_body) + " bytes"
                              : std::string("the request body could not be read"));
            return;
        }
    }
    router.dispatch(req, body, res);
}

void StudioServer::State::setup() {
    add_file_routes(router, ctx);
    add_session_routes(router, ctx);
    add_job_routes(router, ctx);
    const int threads = ctx.config.http_threads;
    http.new_task_queue = [threads] { return new httplib::ThreadPool(static_cast<size_t>(threads)); };
    http.set_payload_max_length(ctx.config.max_body);
    http.set_keep_alive_timeout(2);  // an idle connection holds a worker; short, so a stop is quick
    http.set_read_timeout(10, 0);
    http.set_write_timeout(10, 0);
    // Answers are small and awaited one at a time by a stroke being drawn: without
    // TCP_NODELAY, Nagle's algorithm meeting the browser's delayed ACK holds some for ~40 ms.
    http.set_tcp_nodelay(true);
    // SO_REUSEADDR only: httplib's default also sets SO_REUSEPORT, which lets a second
    // server share the port silently.
    http.set_socket_options([](socket_t sock) {
        int yes = 1;
        ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    });
    const auto plain = [this](const httplib::Request& req, httplib::Response& res) {
        intake(req, res, nullptr);
    };
    const auto with_body = [this](const httplib::Request& req, httplib::Response& res,
                                  const httplib::ContentReader& reader) { intake(req, res, &reader); };
    http.Get(".*", plain);
    http.Options(".*", plain);
    http.Post(".*", plain).Post(".*", with_body);
    http.Put(".*", plain).Put(".*", with_body);
    http.Patch(".*", plain).Patch(".*", with_body);
    http.Delete(".*", plain).Delete(".*", with_body);
    // Answers httplib makes itself (a malformed request line, a Content-Length over the cap).
    const httplib::Server::HandlerWithResponse on_error = [](const httplib::Request&,
                                                             httplib::Response& res) {
        if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
        send_error(res, res.status,
                   res.status == 413 ? "request body too large" : "HTTP error " + std::to_string(res.status));
        return httplib::Server::HandlerResponse::Handled;
    };
    http.set_error_handler(on_error);
    http.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
        send_error(res, 500, "internal error");
    });
}

StudioServer::StudioServer(StudioConfig config) : state_(std::make_unique<State>(std::move(config))) {
    state_->setup();
}

StudioServer::~StudioServer() {
    stop();
}

int StudioServer::bind() {
    State& s = *state_;
    const StudioConfig& c = s.ctx.config;
    const int port =
        c.port == 0 ? s.http.bind_to_any_port(c.host) : (s.http.bind_to_port(c.host, c.port) ? c.port : -1);
    if (port < 0)
        throw tessera::Error(tessera::ErrorKind::io, "cannot listen on " + c.host + ":" +
                                                         std::to_string(c.port) +
                                                         " (in use, or not an address here)");
    s.ctx.port = port;
    s.bound = true;
    return port;
}

void StudioServer::serve() {
    State& s = *state_;
    if (!s.bound) bind();
    s.serving = true;
    if (!s.ctx.stopping) s.http.listen_after_bind();
    s.serving = false;
}

void StudioServer::start() {
    State& s = *state_;
    if (!s.bound) bind();
    s.thread = std::thread([this] { serve(); });
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!s.http.is_running() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    if (!s.http.is_running()) throw tessera::Error(tessera::ErrorKind::io, "the studio server did not start");
}

void StudioServer::stop() {
    State& s = *state_;
    std::lock_guard lock(s.stop_mutex);
    s.ctx.stopping = true;  // event streams end at their next tick
    s.ctx.jobs.stop();      // cancels and joins the jobs
    // httplib's stop() only works once listening has begun, and only once (it asserts).
    bool stopped = false;
    while (s.serving) {
        if (!stopped && s.http.is_running()) {
            s.http.stop();
            stopped = true;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (s.thread.joinable()) s.thread.join();
}

int StudioServer::port() const {
    return state_->ctx.port;
}

std::string StudioServer::url() const {
    const std::string& host = state_->ctx.config.host;
    const bool v6 = host.find(':') != std::string::npos;
    return "http://" + (v6 ? "[" + host + "]" : host) + ":" + std::to_string(port()) + "/";
}

}  // namespace tessera_studio
