// The progress line of a long render: what is rendered, how far (percent of its samples or of
// its time), samples per second, elapsed time, time left, and the estimated error. Written to standard error, refreshed in place on a terminal; on a pipe only
// the final summary is printed, so logs stay readable.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace freezeray {

class Progress {
public:
    // quiet: print nothing at all (tests). `subject` names what is rendered (the integrator),
    // at the start of the line; without one the phase's label stands there.
    explicit Progress(bool quiet = false, std::string subject = "");

    // A new phase of `total_work` units (samples), or of `seconds` wall time when total_work is 0.
    void start(const std::string& label, std::uint64_t total_work, double seconds = 0.0);
    // Adds finished work (thread-safe) and refreshes the line at most a few times a second.
    void advance(std::uint64_t work);
    // Records the latest error estimate for display.
    void set_estimated_error(double relative_mse);
    // Prints the summary line.
    void finish();

    double elapsed_seconds() const;

private:
    void print(bool final_line);

    bool quiet_;
    bool terminal_;
    std::string subject_;
    std::string label_;
    std::uint64_t total_work_ = 0;
    double total_seconds_ = 0.0;
    std::atomic<std::uint64_t> done_{0};
    std::atomic<double> estimated_error_{-1.0};
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point last_print_;
    std::mutex print_mutex_;
};

// "1h 02m 03s", "4.2 s": a duration for people.
std::string format_duration(double seconds);

}  // namespace freezeray
