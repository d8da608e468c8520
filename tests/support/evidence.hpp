// Failure evidence: when a statistical test fails, it writes what a person needs to judge the
// failure (both images, the p-value map, the chi-square table) to a folder and prints the path.
// Tests call these only on failure, e.g.
//     if (!result.passed) FAIL(result.message << "\nevidence: " << write_evidence("furnace", result, images));
#pragma once

#include "chi_square.hpp"
#include "image_tests.hpp"

#include "freezeray/image.hpp"

#include <string>
#include <vector>

namespace freezeray::stats {

// An image to keep, and the file name (without extension) to give it.
struct EvidenceImage {
    std::string name;
    const Image& image;
};

// The folder under which evidence goes: the compile-time FREEZERAY_EVIDENCE_DIR (set by
// tests/CMakeLists.txt to <build>/test-evidence), else "test-evidence" in the working folder.
std::string evidence_directory();

// A test name made safe as one folder name: letters, digits, '-' and '_'; every other run of
// characters becomes one '_'. Never empty, never "." or "..".
std::string sanitize_test_name(const std::string& test_name);

// Writes <evidence_directory>/<sanitized test name>/ afresh: each image as NAME.pfm and `report` as
// report.txt. Returns that folder's path. Never throws: what could not be written is reported on
// standard error and in report.txt, since the evidence must not hide the failure that asked for it.
std::string write_evidence(const std::string& test_name, const std::vector<EvidenceImage>& images,
                           const std::string& report);

// The chi-square evidence: report.txt with the message and the table of every cell, and the
// histograms as images of columns x rows pixels (row 0 at the top is the first row of the table):
// observed.pfm, expected.pfm and deviation.pfm, (observed - expected) / sqrt(expected).
std::string write_evidence(const std::string& test_name, const ChiSquareResult& result);

// The image-test evidence: the given images (both renders, their variances, the known image),
// the result's p-value map as p_values.pfm and its message as report.txt.
std::string write_evidence(const std::string& test_name, const ImageTestResult& result,
                           const std::vector<EvidenceImage>& images);

}  // namespace freezeray::stats
