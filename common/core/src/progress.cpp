// The progress line.
#include "freezeray/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <unistd.h>

namespace freezeray {

std::string format_duration(double seconds) {
    char buffer[64];
    if (!std::isfinite(seconds) || seconds < 0) return "?";
    if (seconds < 60.0) {
        std::snprintf(buffer, sizeof buffer, "%.1f s", seconds);
    } else {
        const long total = static_cast<long>(seconds + 0.5);
        if (total >= 3600)
            std::snprintf(buffer, sizeof buffer, "%ldh %02ldm %02lds", total / 3600, (total / 60) % 60, total % 60);
        else
            std::snprintf(buffer, sizeof buffer, "%ldm %02lds", total / 60, total % 60);
    }
    return buffer;
}

Progress::Progress(bool quiet, std::string subject)
    : quiet_(quiet), terminal_(isatty(STDERR_FILENO) != 0), subject_(std::move(subject)) {
    start_ = last_print_ = std::chrono::steady_clock::now();
}

void Progress::start(const std::string& label, std::uint64_t total_work, double seconds) {
    label_ = label;
    total_work_ = total_work;
    total_seconds_ = seconds;
    done_ = 0;
    estimated_error_ = -1.0;
    start_ = last_print_ = std::chrono::steady_clock::now();
}

double Progress::elapsed_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::advance(std::uint64_t work) {
    done_.fetch_add(work, std::memory_order_relaxed);
    if (quiet_ || !terminal_) return;
    const auto now = std::chrono::steady_clock::now();
    std::unique_lock<std::mutex> lock(print_mutex_, std::try_to_lock);
    if (!lock.owns_lock() || now - last_print_ < std::chrono::milliseconds(250)) return;
    last_print_ = now;
    print(false);
}

void Progress::set_estimated_error(double relative_mse) { estimated_error_ = relative_mse; }

void Progress::finish() {
    if (quiet_) return;
    std::lock_guard<std::mutex> lock(print_mutex_);
    print(true);
}

void Progress::print(bool final_line) {
    const double elapsed = elapsed_seconds();
    const double done = static_cast<double>(done_.load());
    const double rate = elapsed > 0.0 ? done / elapsed : 0.0;
    double remaining = -1.0;
    if (total_work_ > 0 && rate > 0.0) remaining = (static_cast<double>(total_work_) - done) / rate;
    else if (total_seconds_ > 0.0) remaining = total_seconds_ - elapsed;

    // How far: the share of the samples, or of the time budget.
    double fraction = -1.0;
    if (total_work_ > 0) fraction = done / static_cast<double>(total_work_);
    else if (total_seconds_ > 0.0) fraction = elapsed / total_seconds_;
    char line[320];
    int n = std::snprintf(line, sizeof line, "%s: ", subject_.empty() ? label_.c_str() : subject_.c_str());
    if (fraction >= 0.0 && n > 0)
        n += std::snprintf(line + n, sizeof line - n, "%3.0f%% of %s, ", 100.0 * std::min(fraction, 1.0),
                           total_work_ > 0 ? "its samples" : "its time");
    if (n > 0 && n < static_cast<int>(sizeof line))
        n += std::snprintf(line + n, sizeof line - n, "%.3g samples/s, elapsed %s", rate, format_duration(elapsed).c_str());
    if (!final_line && remaining >= 0.0 && n > 0 && n < static_cast<int>(sizeof line))
        n += std::snprintf(line + n, sizeof line - n, ", left %s", format_duration(remaining).c_str());
    const double error = estimated_error_.load();
    if (error >= 0.0 && n > 0 && n < static_cast<int>(sizeof line))
        std::snprintf(line + n, sizeof line - n, ", estimated relMSE %.3g", error);
    if (terminal_)
        std::fprintf(stderr, "\r\033[K%s%s", line, final_line ? "\n" : "");
    else if (final_line)
        std::fprintf(stderr, "%s\n", line);
    std::fflush(stderr);
}

}  // namespace freezeray
