// apps/studio/jobs.cpp — the job runner (jobs.hpp).
#include "apps/studio/jobs.hpp"

#include <algorithm>

#include "tessera/error.hpp"

namespace tessera_studio {

const char* to_string(JobState state) {
    switch (state) {
        case JobState::running:
            return "running";
        case JobState::done:
            return "done";
        case JobState::failed:
            return "failed";
        case JobState::cancelled:
            return "cancelled";
    }
    return "unknown";
}

Json job_json(const std::string& id, const std::string& session, const JobSnapshot& s) {
    return {{"id", id},
            {"session", session},
            {"state", to_string(s.state)},
            {"fraction", s.fraction},
            {"stage", s.stage},
            {"iteration", s.iteration},
            {"iterations", s.iterations},
            {"error", s.error.empty() ? Json() : Json(s.error)},
            {"report", s.report.is_null() ? Json::object() : s.report}};
}

Job::Job(std::string id, std::string session) : id_(std::move(id)), session_(std::move(session)) {}

JobSnapshot Job::snapshot() const {
    std::lock_guard lock(mutex_);
    return snapshot_;
}

JobSnapshot Job::wait_for_change(std::uint64_t seen, std::chrono::milliseconds timeout) const {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, timeout, [&] { return snapshot_.version != seen; });
    return snapshot_;
}

void Job::cancel() {
    cancel_.store(true);
    std::lock_guard lock(mutex_);
    ++snapshot_.version;  // wakes event streams, which then report the cancel once it lands
    changed_.notify_all();
}

bool Job::on_progress(const tessera::ProgressEvent& event) {
    {
        std::lock_guard lock(mutex_);
        snapshot_.fraction = std::clamp(event.fraction, 0.0, 1.0);
        snapshot_.stage = event.stage;
        snapshot_.iteration = event.iteration;
        snapshot_.iterations = event.iterations;
        ++snapshot_.version;
    }
    changed_.notify_all();
    return !cancel_requested();
}

void Job::finish(JobState state, Json report, std::string error) {
    {
        std::lock_guard lock(mutex_);
        snapshot_.state = state;
        if (state == JobState::done) snapshot_.fraction = 1.0;
        snapshot_.stage = to_string(state);
        snapshot_.report = std::move(report);
        snapshot_.error = std::move(error);
        ++snapshot_.version;
    }
    changed_.notify_all();
}

JobRunner::JobRunner(int max_running, size_t max_kept) : max_running_(max_running), max_kept_(max_kept) {}

JobRunner::~JobRunner() {
    stop();
}

namespace {

struct Outcome {
    JobState state = JobState::done;
    Json report;
    std::string error;
};

// Runs `work` and says how it ended; nothing escapes the job's thread.
Outcome run_work(Job& job, const JobRunner::Work& work) {
    try {
        return {JobState::done, work([&job](const tessera::ProgressEvent& e) { return job.on_progress(e); }),
                ""};
    } catch (const tessera::Error& e) {
        if (e.kind() == tessera::ErrorKind::cancelled) return {JobState::cancelled, {}, ""};
        return {JobState::failed, {}, e.what()};
    } catch (const std::exception& e) {
        return {JobState::failed, {}, std::string("internal error: ") + e.what()};
    }
}

}  // namespace

std::shared_ptr<Job> JobRunner::start(const std::string& id, const std::string& session, Work work) {
    std::lock_guard lock(mutex_);
    reap_locked();
    if (stopped_ || running_locked() >= max_running_) return nullptr;
    auto job = std::make_shared<Job>(id, session);
    auto finished = std::make_shared<std::atomic<bool>>(false);
    std::thread thread([job, finished, work = std::move(work)] {
        Outcome outcome = run_work(*job, work);
        // The slot is free before the end is visible: a client that sees it may start the next job.
        finished->store(true);
        job->finish(outcome.state, std::move(outcome.report), std::move(outcome.error));
    });
    threads_.push_back({job, finished, std::move(thread)});
    jobs_[id] = job;
    order_.push_back(id);
    forget_old_locked();
    return job;
}

std::shared_ptr<Job> JobRunner::find(const std::string& id) const {
    std::lock_guard lock(mutex_);
    const auto it = jobs_.find(id);
    return it == jobs_.end() ? nullptr : it->second;
}

bool JobRunner::has_room() const {
    std::lock_guard lock(mutex_);
    return !stopped_ && running_locked() < max_running_;
}

int JobRunner::running_locked() const {
    int running = 0;
    for (const Thread& t : threads_) running += t.finished->load() ? 0 : 1;
    return running;
}

// Joins the threads whose work has returned (their join is immediate).
void JobRunner::reap_locked() {
    for (auto it = threads_.begin(); it != threads_.end();) {
        if (!it->finished->load()) {
            ++it;
            continue;
        }
        it->thread.join();
        it = threads_.erase(it);
    }
}

// Keeps at most max_kept_ jobs readable, dropping the oldest finished ones.
void JobRunner::forget_old_locked() {
    for (auto it = order_.begin(); jobs_.size() > max_kept_ && it != order_.end();) {
        const auto job = jobs_.find(*it);
        if (job != jobs_.end() && job->second->snapshot().state == JobState::running) {
            ++it;
            continue;
        }
        if (job != jobs_.end()) jobs_.erase(job);
        it = order_.erase(it);
    }
}

void JobRunner::stop() {
    std::vector<Thread> threads;
    {
        std::lock_guard lock(mutex_);
        stopped_ = true;
        for (Thread& t : threads_) t.job->cancel();
        threads.swap(threads_);
    }
    for (Thread& t : threads) t.thread.join();
}

}  // namespace tessera_studio
