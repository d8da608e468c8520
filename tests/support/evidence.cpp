// Failure evidence written to a folder per failing test.
#include "evidence.hpp"

#include <cctype>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace freezeray::stats {

namespace {

// Runs one writing step; on failure, says so on standard error and returns the reason as a line.
template <typename Step>
std::string attempt(const std::string& what, const Step& step) {
    try {
        step();
        return {};
    } catch (const std::exception& error) {
        std::cerr << "evidence: could not write " << what << ": " << error.what() << "\n";
        return "could not write " + what + ": " + error.what() + "\n";
    }
}

// The cells of a chi-square histogram as an image, one pixel per cell, grey.
Image histogram_image(const ChiSquareResult& result, const std::vector<double>& values) {
    Image image(result.columns, result.rows);
    for (std::size_t i = 0; i < values.size() && i < image.pixel_count(); ++i)
        image[i] = Spectrum(static_cast<float>(values[i]));
    return image;
}

}  // namespace

std::string evidence_directory() {
#ifdef FREEZERAY_EVIDENCE_DIR
    return FREEZERAY_EVIDENCE_DIR;
#else
    return "test-evidence";
#endif
}

std::string sanitize_test_name(const std::string& test_name) {
    constexpr std::size_t maximum_length = 120;
    std::string name;
    for (const char c : test_name) {
        const bool safe = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
        if (safe)
            name += c;
        else if (!name.empty() && name.back() != '_')
            name += '_';
        if (name.size() >= maximum_length) break;
    }
    while (!name.empty() && name.back() == '_') name.pop_back();
    return name.empty() ? "unnamed-test" : name;
}

std::string write_evidence(const std::string& test_name, const std::vector<EvidenceImage>& images,
                           const std::string& report) {
    namespace fs = std::filesystem;
    const fs::path folder = fs::path(evidence_directory()) / sanitize_test_name(test_name);
    std::string problems = attempt("folder " + folder.string(), [&] {
        fs::remove_all(folder);  // evidence of an earlier run must not mix with this one
        fs::create_directories(folder);
    });
    for (const EvidenceImage& image : images)
        problems += attempt(image.name + ".pfm", [&] { write_image((folder / (image.name + ".pfm")).string(), image.image); });
    problems += attempt("report.txt", [&] {
        std::ofstream file(folder / "report.txt");
        file << "test: " << test_name << "\n\n" << report << "\n";
        if (!problems.empty()) file << "\nincomplete evidence:\n" << problems;
        if (!file) throw std::runtime_error("the file could not be written");
    });
    return folder.string();
}

std::string write_evidence(const std::string& test_name, const ChiSquareResult& result) {
    std::vector<double> deviation(result.observed.size(), 0.0);
    for (std::size_t i = 0; i < deviation.size(); ++i)
        if (result.expected[i] > 0.0)
            deviation[i] = (result.observed[i] - result.expected[i]) / std::sqrt(result.expected[i]);
    const Image observed = histogram_image(result, result.observed);
    const Image expected = histogram_image(result, result.expected);
    const Image deviation_image = histogram_image(result, deviation);
    return write_evidence(test_name, {{"observed", observed}, {"expected", expected}, {"deviation", deviation_image}},
                          result.table());
}

std::string write_evidence(const std::string& test_name, const ImageTestResult& result,
                           const std::vector<EvidenceImage>& images) {
    std::vector<EvidenceImage> all = images;
    all.push_back({"p_values", result.p_value_map});
    return write_evidence(test_name, all, result.message);
}

}  // namespace freezeray::stats
