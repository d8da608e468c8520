// Specular-diffuse-specular (SDS) paths: light that reaches a diffuse or glossy surface through a
// specular one, seen by the camera through a specular one (the floor under water, seen through
// the water and lit through it). No connection crosses a specular surface, so of all the
// strategies of bidirectional path tracing only one can make such a path: the camera subpath
// that leaves the surface, passes the specular one and happens to hit the light (Veach, "Robust
// Monte Carlo Methods for Light Transport Simulation", 1997, chapter 10; Kaplanyan and
// Dachsbacher, "Path Space Regularization for Holistic and Robust Light Transport", 2013). With a
// small light that strategy's density is tiny and its MIS weight 1: the estimators that sample
// paths independently (path tracing, bidirectional path tracing) get a heavy tail of rare, very
// bright samples, which a short pilot render seldom meets and so cannot measure.
//
// The probe measures how much of an image rests on such paths, with rays only: it follows camera
// rays through their specular bounces to the first diffuse or glossy surface and asks, with a few
// light samples there, how much of the light that would arrive unoccluded is stopped by a
// specular surface. On request it also measures how heavy the tail is: how often the one
// strategy, a direction sampled from the BSDF there and followed through specular bounces,
// reaches an emitter (camera_strategy_chance).
#pragma once

#include "freezeray/integrator_advice.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace freezeray {
class Scene;
class LightSampler;
}  // namespace freezeray

namespace freezeray::ch05 {

// Above this share of the image lit by SDS paths, only integrators that explore the paths they
// find (the Metropolis chains of chapter 05) are trusted: `auto` pilots only those, and the
// suggestion of `info` and the default integrator of `render` is one of them. One pixel in
// twenty: the book's scenes measure 0.007 or less, or 0.64 (water-caustic), so any limit from
// 0.01 to 0.6 makes the same choices (book chapter 11, "Paths no pilot measures").
constexpr double SdsShareLimit = 0.05;

struct SdsShare {
    double share = 0.0;           // the mean over the probes, in [0, 1]
    // The share of probes whose camera ray reached a lit diffuse or glossy surface through a
    // specular bounce or more (those with a value that may be non-zero).
    double lit_through_specular_view = 0.0;
    double standard_error = 0.0;  // of `share`, from the probes' spread
    std::size_t probes = 0;
    // How the one strategy finds those paths (when SdsProbeSettings::camera_strategy_tries > 0):
    // of `camera_strategy_tries` directions sampled from the BSDF at the surfaces lit through a
    // specular one, followed through specular bounces, `camera_strategy_hits` reached an emitter.
    std::uint64_t camera_strategy_tries = 0;
    std::uint64_t camera_strategy_hits = 0;
};

// The chance p that the camera strategy finds the light from a surface lit through a specular
// one, with a 95 % upper bound (the Poisson bound on the hits, for few of them); and the tail it
// leaves: where a pixel's light comes only from hits of chance p, each worth 1/p of the pixel's
// value, the relative variance of one sample is 1/p - 1. Over the image, about share / p: the
// relMSE these paths alone add at one sample per pixel, in expectation (a heavy tail's typical
// run lies below it).
struct CameraStrategyChance {
    double p = 0.0;            // hits / tries
    double p_upper = 0.0;      // 95 % upper bound
    double tail_per_sample = 0.0;  // share / p; infinite when no try hit
    double tail_lower = 0.0;   // share / p_upper
};
CameraStrategyChance camera_strategy_chance(const SdsShare& sds);

struct SdsProbeSettings {
    std::size_t probes = 1u << 16;  // camera rays, at uniformly random film positions
    int light_samples = 4;          // light samples at each probe's diffuse or glossy surface
    int max_specular_bounces = 8;   // a camera ray that keeps bouncing specularly longer counts 0
    // Tries of the camera strategy in all, spread evenly over the probes' surfaces lit through a
    // specular one (0: not measured).
    std::uint64_t camera_strategy_tries = 0;
    std::uint64_t seed = 0;
    int threads = 0;                // 0: every core
};

// Each probe's value is 0 unless its camera ray reaches a diffuse or glossy surface after one
// specular bounce or more; then it is the share of the light samples' unoccluded contribution
// there (luminance of Li |cos| / pdf) whose shadow ray first meets a surface with specular lobes
// only, out of the contribution of the samples that are either unoccluded or so blocked (samples
// an opaque surface blocks carry no light along any path and are left out). Lights are chosen by
// `lights` when given, else uniformly. The scene must have a camera.
SdsShare measure_sds_share(const Scene& scene, const LightSampler* lights, const SdsProbeSettings& settings);

// Why a Markov chain (mlt) suits an image with this SDS share, or nothing below SdsShareLimit.
std::optional<std::string> chain_advice(double sds_share);

// Chapter 05's rule of integrator_advice.hpp: the probe, where the scene has specular surfaces,
// a camera and lights; with a detailed request also the camera strategy's chance, and for `info`
// the lines that say what was measured.
std::optional<std::string> advise_chain(const Scene& scene, const AdviceRequest& request);

}  // namespace freezeray::ch05
