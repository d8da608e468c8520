// Image error metrics against values worked out by hand on tiny images, and SSIM's behaviour.
#include "freezeray/error.hpp"
#include "freezeray/metrics.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <string>

using namespace freezeray;

namespace {

// Two 2x1 images with small whole numbers, so that the arithmetic is easy to follow:
//     image:     (1, 2, 3)  (0, 0, 4)
//     reference: (1, 1, 1)  (1, 0, 2)
//     x - r:     (0, 1, 2)  (-1, 0, 2)
Image hand_image() {
    Image image(2, 1);
    image.at(0, 0) = Spectrum(1, 2, 3);
    image.at(1, 0) = Spectrum(0, 0, 4);
    return image;
}
Image hand_reference() {
    Image reference(2, 1);
    reference.at(0, 0) = Spectrum(1, 1, 1);
    reference.at(1, 0) = Spectrum(1, 0, 2);
    return reference;
}

// A 32x24 image with smooth gradients and a few edges, in [0, 1].
Image structured_image() {
    Image image(32, 24);
    for (int y = 0; y < 24; ++y) {
        for (int x = 0; x < 32; ++x) {
            const float stripe = ((x / 4 + y / 6) % 2 == 0) ? 0.2f : 0.0f;
            image.at(x, y) = Spectrum(0.1f + 0.6f * x / 31.0f + stripe, 0.3f + 0.5f * y / 23.0f, 0.5f + stripe);
        }
    }
    return image;
}

// `image` plus Gaussian noise of standard deviation `amplitude`; the same seed each time, so a
// larger amplitude scales the very same noise pattern.
Image with_noise(const Image& image, float amplitude) {
    std::mt19937 random(12345);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    Image noisy = image;
    for (Spectrum& pixel : noisy.pixels()) {
        for (int c = 0; c < 3; ++c) pixel[c] += amplitude * normal(random);
    }
    return noisy;
}

}  // namespace

TEST_CASE("MSE, RMSE and PSNR match the hand computation", "[unit][metrics]") {
    // Squared differences: 0, 1, 4, 1, 0, 4; sum 10 over 2 pixels x 3 channels: MSE = 10 / 6.
    CHECK(mse(hand_image(), hand_reference()) == Approx(10.0 / 6.0));
    CHECK(rmse(hand_image(), hand_reference()) == Approx(std::sqrt(10.0 / 6.0)));
    // PSNR with peak 4: 10 log10(16 / (10 / 6)) = 10 log10(9.6) = 9.8227 dB.
    CHECK(psnr(hand_image(), hand_reference(), 4.0) == Approx(9.822712));
    // Peak 1 (the default): 10 log10(1 / (10 / 6)) = 10 log10(0.6) = -2.2185 dB.
    CHECK(psnr(hand_image(), hand_reference()) == Approx(-2.218487));
}

TEST_CASE("relative MSE and MAPE match the hand computation", "[unit][metrics]") {
    // relMSE terms (x - r)^2 / (r^2 + 0.01):
    //     pixel 0: 0 / 1.01, 1 / 1.01, 4 / 1.01    pixel 1: 1 / 1.01, 0 / 0.01, 4 / 4.01
    // sum = 6 / 1.01 + 4 / 4.01 = 5.940594 + 0.997506 = 6.938100; mean = 1.156350.
    CHECK(relative_mse(hand_image(), hand_reference()) == Approx((6.0 / 1.01 + 4.0 / 4.01) / 6.0));
    CHECK(relative_mse(hand_image(), hand_reference()) == Approx(1.156350));
    // MAPE terms |x - r| / (|r| + 0.01):
    //     pixel 0: 0 / 1.01, 1 / 1.01, 2 / 1.01    pixel 1: 1 / 1.01, 0 / 0.01, 2 / 2.01
    // sum = 4 / 1.01 + 2 / 2.01 = 3.960396 + 0.995025 = 4.955421; mean = 0.825904.
    CHECK(mape(hand_image(), hand_reference()) == Approx((4.0 / 1.01 + 2.0 / 2.01) / 6.0));
    CHECK(mape(hand_image(), hand_reference()) == Approx(0.825904));
    // A larger epsilon, 1: relMSE = (0/2 + 1/2 + 4/2 + 1/2 + 0/1 + 4/5) / 6 = 3.8 / 6.
    CHECK(relative_mse(hand_image(), hand_reference(), 1.0) == Approx(3.8 / 6.0));
}

TEST_CASE("identical images have zero error and infinite PSNR", "[unit][metrics]") {
    const Image image = structured_image();
    CHECK(mse(image, image) == 0.0);
    CHECK(rmse(image, image) == 0.0);
    CHECK(relative_mse(image, image) == 0.0);
    CHECK(mape(image, image) == 0.0);
    CHECK(psnr(image, image) == std::numeric_limits<double>::infinity());
    CHECK(ssim(image, image) == 1.0);
    CHECK(ssim(Image(3, 2), Image(3, 2)) == 1.0);  // black: L falls back to 1
}

TEST_CASE("SSIM matches the hand computation on single windows", "[unit][metrics]") {
    // Grey images are their own luminance (the Rec. 709 weights sum to 1).
    // Constant 0.5 against constant 1: variances are 0, so only the luminance term is left:
    //     L = 1, C1 = 0.0001:  (2 * 0.5 * 1 + C1) / (0.25 + 1 + C1) = 1.0001 / 1.2501 = 0.800016.
    CHECK(ssim(Image(4, 3, Spectrum(0.5f)), Image(4, 3, Spectrum(1.0f))) == Approx(1.0001 / 1.2501).epsilon(1e-5));

    // A 2x1 image (0, 1) against (1, 0): one window, N = 2, means 0.5 and 0.5,
    //     variances (0.25 + 0.25) / (N - 1) = 0.5, covariance (-0.25 - 0.25) / 1 = -0.5,
    //     C1 = 0.0001, C2 = 0.0009 (L = 1):
    //     SSIM = (0.5 + C1)(-1 + C2) / ((0.5 + C1)(1 + C2)) = -0.9991 / 1.0009 = -0.998202.
    Image left_lit(2, 1), right_lit(2, 1);
    left_lit.at(1, 0) = Spectrum(1.0f);
    right_lit.at(0, 0) = Spectrum(1.0f);
    CHECK(ssim(left_lit, right_lit) == Approx(-0.9991 / 1.0009).epsilon(1e-5));

    // L is the reference's peak luminance: scaling both images keeps the score.
    Image bright_left = left_lit, bright_right = right_lit;
    for (Spectrum& pixel : bright_left.pixels()) pixel *= 100.0f;
    for (Spectrum& pixel : bright_right.pixels()) pixel *= 100.0f;
    CHECK(ssim(bright_left, bright_right) == Approx(ssim(left_lit, right_lit)).epsilon(1e-5));
}

TEST_CASE("SSIM falls steadily as noise grows", "[unit][metrics]") {
    const Image reference = structured_image();
    double previous = ssim(reference, reference);
    for (float amplitude : {0.005f, 0.02f, 0.05f, 0.1f, 0.3f, 1.0f}) {
        const double score = ssim(with_noise(reference, amplitude), reference);
        INFO("noise amplitude " << amplitude << ": SSIM " << score);
        CHECK(score < previous);
        CHECK(score > -1.0);
        previous = score;
    }
    CHECK(ssim(with_noise(reference, 0.005f), reference) > 0.9);
    CHECK(previous < 0.5);
}

TEST_CASE("every metric refuses images of different sizes", "[unit][metrics]") {
    const Image wide(3, 2), tall(2, 3);
    try {
        check_same_size(wide, tall, "render.exr");
        FAIL("no InputError for different sizes");
    } catch (const InputError& error) {
        CHECK(error.where() == "render.exr");
        CHECK(error.problem() == "is 3x2 but the reference is 2x3");
    }
    CHECK_NOTHROW(check_same_size(wide, Image(3, 2), "render.exr"));
    CHECK_THROWS_AS(mse(wide, tall), InputError);
    CHECK_THROWS_AS(relative_mse(wide, tall), InputError);
    CHECK_THROWS_AS(rmse(wide, tall), InputError);
    CHECK_THROWS_AS(psnr(wide, tall), InputError);
    CHECK_THROWS_AS(mape(wide, tall), InputError);
    CHECK_THROWS_AS(ssim(wide, tall), InputError);
    CHECK_THROWS_AS(mse(Image(), Image()), InputError);  // nothing to average over
    CHECK_THROWS_AS(ssim(Image(), Image()), InputError);
}
