// Printing measurement rows as a table or as JSON lines.
#include "benchmark_report.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace freezeray::benchmark {

namespace {

template <typename T>
nlohmann::ordered_json or_null(const std::optional<T>& value) {
    return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

template <typename T>
std::string or_dash(const std::optional<T>& value, const char* pattern) {
    return value ? format(pattern, static_cast<double>(*value)) : std::string("-");
}

}  // namespace

void print_table_header(std::ostream& out) {
    char line[256];
    std::snprintf(line, sizeof line, "%-12s %-8s %7s %9s %10s %10s %10s %10s %8s %6s\n", "accel", "kind", "threads",
                  "rays", "Mrays/s", "median ms", "build ms", "memory MB", "differ", "ties");
    out << line << std::string(97, '-') << "\n";
}

void print_table_row(std::ostream& out, const MeasurementRow& row) {
    char line[256];
    std::snprintf(line, sizeof line, "%-12s %-8s %7d %9zu %10.4g %10.2f %10.1f %10s %8s %6s\n", row.accel.c_str(),
                  ray_kind_name(row.kind), row.threads, row.rays, row.mrays_per_second, row.median_milliseconds,
                  row.build_milliseconds, or_dash(row.memory_megabytes, "%.1f").c_str(),
                  or_dash(row.differ_from_embree, "%.0f").c_str(), or_dash(row.ties, "%.0f").c_str());
    out << line << std::flush;
}

std::string json_line(const MeasurementRow& row) {
    // An ordered_json keeps the fields in the order written here, the order of the table.
    nlohmann::ordered_json j;
    j["accel"] = row.accel;
    j["kind"] = ray_kind_name(row.kind);
    j["threads"] = row.threads;
    j["rays"] = row.rays;
    j["mrays_per_s"] = row.mrays_per_second;
    j["median_ms"] = row.median_milliseconds;
    j["reps"] = row.repetitions;
    j["build_ms"] = row.build_milliseconds;
    j["memory_mb"] = or_null(row.memory_megabytes);
    j["differ_from_embree"] = or_null(row.differ_from_embree);
    j["ties"] = or_null(row.ties);
    return j.dump();
}

}  // namespace freezeray::benchmark
