// apps/studio/jobs.hpp — long operations off the request thread (docs/studio.md, "Jobs").
// A job runs one piece of work on its own thread, records the progress events the library
// sends (tessera/progress.hpp), and ends done, failed or cancelled; a cancel makes the next
// progress call return false, so the library throws tessera::Cancelled. At most
// `max_running` jobs run at once (start() answers nullptr beyond, the server's 503); the
// last `max_kept` finished jobs stay readable. Every thread is joined by stop().
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "apps/studio/api_json.hpp"
#include "tessera/progress.hpp"

namespace tessera_studio {

enum class JobState { running, done, failed, cancelled };
const char* to_string(JobState state);

// What a client sees of a job. `version` grows with every change, for waiting on one.
struct JobSnapshot {
    JobState state = JobState::running;
    double fraction = 0.0;
    std::string stage = "starting";
    int iteration = 0, iterations = 0;
    std::string error;
    Json report;
    std::uint64_t version = 0;
};

// {"id", "session", "state", "fraction", "stage", "iteration", "iterations", "error", "report"}.
Json job_json(const std::string& id, const std::string& session, const JobSnapshot& s);

class Job {
public:
    Job(std::string id, std::string session);
    const std::string& id() const { return id_; }
    const std::string& session() const { return session_; }

    JobSnapshot snapshot() const;
    // The snapshot once its version differs from `seen`, or after `timeout` as it is.
    JobSnapshot wait_for_change(std::uint64_t seen, std::chrono::milliseconds timeout) const;
    void cancel();
    bool cancel_requested() const { return cancel_.load(); }

    // The job's progress callback: records the event; false once cancelled.
    bool on_progress(const tessera::ProgressEvent& event);
    void finish(JobState state, Json report, std::string error);

private:
    const std::string id_, session_;
    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;
    JobSnapshot snapshot_;
    std::atomic<bool> cancel_{false};
};

class JobRunner {
public:
    // The work: returns the report; throws tessera::Cancelled when its progress said stop,
    // anything else when it failed (the message becomes the job's error).
    using Work = std::function<Json(const tessera::Progress&)>;

    JobRunner(int max_running, size_t max_kept);
    ~JobRunner();
    JobRunner(const JobRunner&) = delete;
    JobRunner& operator=(const JobRunner&) = delete;

    // A new job running `work` under id `id`; nullptr when max_running jobs run or after stop().
    std::shared_ptr<Job> start(const std::string& id, const std::string& session, Work work);
    std::shared_ptr<Job> find(const std::string& id) const;
    // Whether another job can start now (a caller checks before preparing one).
    bool has_room() const;
    // Cancels every running job and joins every thread; start() refuses from then on.
    void stop();

private:
    struct Thread {
        std::shared_ptr<Job> job;
        std::shared_ptr<std::atomic<bool>> finished;
        std::thread thread;
    };
    void reap_locked();
    int running_locked() const;
    void forget_old_locked();

    mutable std::mutex mutex_;
    std::map<std::string, std::shared_ptr<Job>> jobs_;
    std::deque<std::string> order_;  // ids by start, for forgetting the oldest finished
    std::vector<Thread> threads_;
    const int max_running_;
    const size_t max_kept_;
    bool stopped_ = false;
};

}  // namespace tessera_studio
