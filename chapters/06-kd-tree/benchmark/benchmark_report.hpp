// The benchmark's results: one row per tracer, ray kind and thread count, printed as a table
// for people or as JSON lines for scripts (the book's tables and plots).
#pragma once

#include "ray_batch.hpp"

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>

namespace freezeray::benchmark {

struct MeasurementRow {
    std::string accel;                 // "bruteforce", "kdtree", ..., or "embree"
    RayKind kind = RayKind::Primary;
    int threads = 1;
    std::size_t rays = 0;
    double mrays_per_second = 0.0;     // at the median time
    double median_milliseconds = 0.0;  // of the timed runs
    int repetitions = 0;               // timed runs (after one warm-up run)
    double build_milliseconds = 0.0;
    std::optional<double> memory_megabytes;         // when the tracer reports it
    std::optional<std::size_t> differ_from_embree;  // empty without Embree, and for Embree's own rows
    std::optional<std::size_t> ties;                // empty as well, and for shadow rays
};

// The table's column titles and a rule under them.
void print_table_header(std::ostream& out);
// One line of the table; "-" for what is unknown.
void print_table_row(std::ostream& out, const MeasurementRow& row);

// One JSON object on one line, e.g. {"accel": "kdtree", "kind": "diffuse", "threads": 1,
// "rays": 259466, "mrays_per_s": 1.23, ...}; unknown values are null.
std::string json_line(const MeasurementRow& row);

}  // namespace freezeray::benchmark
