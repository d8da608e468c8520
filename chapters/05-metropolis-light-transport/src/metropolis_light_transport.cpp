// Metropolis light transport in primary sample space (book chapter 05; Kelemen et al. 2002;
// pbrt-v3, section 16.4).
#include "freezeray/ch05/metropolis_light_transport.hpp"

#include "freezeray/cache_line_allocator.hpp"
#include "freezeray/error.hpp"
#include "freezeray/parallel.hpp"
#include "freezeray/progress.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/ch04/splat_batches.hpp"
#include "freezeray/ch02/path_tracer.hpp"
#include "freezeray/ch03/piecewise_constant.hpp"
#include "freezeray/ch04/subpaths.hpp"
#include "freezeray/ch05/metropolis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace freezeray::ch05 {

namespace {

constexpr std::uint64_t BootstrapSamplesPerUnit = 256;

// Each chain's own generators once it runs: one for its mutations, one for its acceptance
// decisions (deterministic per (seed, chain), whatever thread runs it).
PCG32 mutation_stream(std::uint64_t seed, std::uint64_t chain) { return make_chain_stream(seed, (1ULL << 62) + chain); }
PCG32 acceptance_stream(std::uint64_t seed, std::uint64_t chain) { return make_chain_stream(seed, (1ULL << 61) + chain); }

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, a, b, c, d);
    return text;
}

// One Markov chain: its state (the primary samples and what they evaluate to) and its counts.
// Neighbouring chains mutate at the same time on different threads: each starts on a cache line
// of its own, so that one's counters never share a line with the next one's state (see Sampler).
struct alignas(CacheLineBytes) Chain {
    PrimarySamples samples;
    int segments = 0;  // multiplexed MLT: the chain's path length (fixed: chosen by its start)
    PCG32 acceptance;
    PathContributions current, proposed;
    std::uint64_t proposed_count = 0, accepted_count = 0;
    std::uint64_t large_proposed = 0, large_accepted = 0;
    std::uint64_t invalid = 0;
};

}  // namespace

PCG32 bootstrap_stream(std::uint64_t seed, std::uint64_t index) { return make_chain_stream(seed, index); }

Vec2 start_path(const Scene& scene, PrimarySamples& samples, ScratchArena& arena, PathContributions& out) {
    out.splats.clear();
    out.value = 0.0f;
    out.invalid = 0;
    arena.reset();
    // The film position is part of the state: a chain moves over the whole image.
    samples.start_stream(ch04::CameraStream);
    const Camera& camera = *scene.camera;
    return Vec2(samples.next_float() * static_cast<float>(camera.width()),
                samples.next_float() * static_cast<float>(camera.height()));
}

// BOOK(evaluate-path)
void evaluate_path(const Scene& scene, const ch03::FixedLightSampler& lights, const ch04::BidirectionalSettings& settings,
                   PrimarySamples& samples, ScratchArena& arena, ch04::SubpathStorage& storage, PathContributions& out) {
    const Vec2 film = start_path(scene, samples, arena, out);
    ch04::bidirectional_sample(scene, lights, settings, film, samples, arena, storage,
                               [&](const ch04::BidirectionalContribution& c) {
                                   if (is_black(c.weighted)) return;
                                   if (!is_valid_radiance(c.weighted)) {
                                       ++out.invalid;
                                       return;
                                   }
                                   out.splats.push_back({c.raster_position, c.weighted});
                                   out.value += luminance(c.weighted);
                               });
}
// END BOOK

// BOOK(bootstrap)
Bootstrap run_bootstrap(const Scene& scene, const ch03::FixedLightSampler& lights, const ch04::BidirectionalSettings& bidirectional,
                        const MltSettings& settings, std::uint64_t seed, int threads) {
    Bootstrap result;
    threads = resolve_thread_count(threads);
    const std::uint64_t count = settings.bootstrap_samples;
    result.values.assign(count, 0.0f);
    const std::uint64_t units = (count + BootstrapSamplesPerUnit - 1) / BootstrapSamplesPerUnit;
    std::vector<ScratchArena> arenas(static_cast<std::size_t>(threads));
    parallel_for(units, threads, [&](std::size_t unit, int thread) {
        thread_local ch04::SubpathStorage storage;
        PathContributions contributions;
        const std::uint64_t first = unit * BootstrapSamplesPerUnit;
        const std::uint64_t last = std::min(count, first + BootstrapSamplesPerUnit);
        for (std::uint64_t i = first; i < last; ++i) {
            // Each bootstrap sample is the first state of a chain seeded by its index: a chain
            // that starts from sample i regenerates it exactly.
            PrimarySamples samples(bootstrap_stream(seed, i), settings.sigma, settings.large_step_probability,
                                   ch04::BidirectionalStreamCount);
            ScratchArena& arena = arenas[static_cast<std::size_t>(thread)];
            if (settings.multiplexed)
                evaluate_multiplexed_path(scene, lights, bidirectional, multiplexed_segments(i, bidirectional.max_depth),
                                          samples, arena, storage, contributions);
            else
                evaluate_path(scene, lights, bidirectional, samples, arena, storage, contributions);
            result.values[i] = contributions.value;
        }
    });
    // b, the integral of I over primary sample space, and the standard error of its estimate.
    double sum = 0.0, sum_squares = 0.0;
    for (const float v : result.values) {
        sum += v;
        sum_squares += static_cast<double>(v) * v;
    }
    const auto n = static_cast<double>(count);
    result.b = count > 0 ? sum / n : 0.0;
    if (count > 1)
        result.standard_error = std::sqrt(std::max(0.0, (sum_squares - sum * sum / n) / (n - 1.0)) / n);
    if (settings.multiplexed) {
        // Each length had a max_depth-th of the samples: b is the sum over lengths of their means.
        result.b *= bidirectional.max_depth;
        result.standard_error *= bidirectional.max_depth;
    }
    return result;
}
// END BOOK

MltSettings read_mlt_settings(const Parameters& p, int max_depth, bool multiplexed) {
    MltSettings s;
    s.max_depth = max_depth;
    s.multiplexed = multiplexed;
    s.large_step_probability = p.get_float("mlt_large_step", s.large_step_probability);
    if (!(s.large_step_probability > 0.0f && s.large_step_probability <= 1.0f))
        throw InputError(p.where("mlt_large_step"), "must be a probability in (0, 1]");
    s.sigma = p.get_float("mlt_sigma", s.sigma);
    if (!(s.sigma > 0.0f && s.sigma <= 1.0f))
        throw InputError(p.where("mlt_sigma"), "must be in (0, 1] (a step in primary sample space, whose side is 1)");
    const long long bootstrap = p.get_long("mlt_bootstrap", static_cast<long long>(s.bootstrap_samples));
    if (bootstrap < 1 || bootstrap > (1LL << 32)) throw InputError(p.where("mlt_bootstrap"), "must be between 1 and 2^32");
    s.bootstrap_samples = static_cast<std::uint64_t>(bootstrap);
    const long long chains = p.get_long("mlt_chains", s.chains);
    if (chains < 1 || chains > (1 << 20)) throw InputError(p.where("mlt_chains"), "must be between 1 and 2^20");
    s.chains = static_cast<int>(chains);
    return s;
}

MetropolisLightTransport::MetropolisLightTransport(const MltSettings& settings) : settings_(settings) {
    if (settings_.max_depth <= 0) settings_.max_depth = ch02::DefaultMaxDepth;
}

RenderResult MetropolisLightTransport::render(const Scene& scene, const RenderSettings& settings, Progress& progress) const {
    if (settings.resume)
        throw InputError("--resume", "an mlt render cannot be resumed: its Markov chains' states are not saved; render "
                                     "again with another --seed and `merge` the two renders");
    const MltSettings& mlt = settings_;

    const ch03::FixedLightSampler lights(scene.lights, ch03::LightSelection::Power);
    const ch04::BidirectionalSettings bidirectional{mlt.max_depth, ch03::MisHeuristic::Power, ""};
    const Camera& camera = *scene.camera;
    const int width = camera.width(), height = camera.height();
    const auto pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
    const int threads = resolve_thread_count(settings.threads);

    RenderResult result;
    ch04::SplatBatches rounds(settings, progress, pixels);  // the bootstrap's time counts as render time
    const std::string name = mlt.multiplexed ? "mlt-multiplexed" : "mlt";  // for its notes and warnings
    ch04::SplatFilm film(width, height);
    // --sample-offset gives another, independent render of the same seed (for `merge`): MLT has
    // no per-pixel sample indices, so the offset enters its seed.
    const std::uint64_t seed =
        settings.first_sample == 0 ? settings.seed : mix_bits(settings.seed ^ mix_bits(settings.first_sample));
    const Bootstrap bootstrap = run_bootstrap(scene, lights, bidirectional, mlt, seed, threads);
    if (!(bootstrap.b > 0.0)) {
        result.warnings.push_back(name + ": none of the " + std::to_string(mlt.bootstrap_samples) +
                                  " bootstrap paths carried light, so no chain can start: the image is black. The "
                                  "scene's lights may be unreachable from the camera, or too rare for the bootstrap "
                                  "to find (raise --mlt-bootstrap)");
    } else {
        // BOOK(chains)
        // Each chain starts from a bootstrap sample chosen in proportion to its value: the
        // chains start in the stationary distribution, so no start-up bias (Veach 1997,
        // section 11.3.1). A chain regenerates its sample from the sample's own generator.
        const ch03::PiecewiseConstant1D starts(bootstrap.values);
        const auto chain_count = static_cast<std::size_t>(std::max(1, mlt.chains));
        std::vector<Chain> chains;
        chains.reserve(chain_count);
        PCG32 chooser = make_chain_stream(seed, 1ULL << 60);
        for (std::size_t c = 0; c < chain_count; ++c) {
            const std::size_t index = starts.sample_discrete(chooser.next_float());
            chains.push_back(Chain{PrimarySamples(bootstrap_stream(seed, index), mlt.sigma,
                                                  mlt.large_step_probability, ch04::BidirectionalStreamCount),
                                   mlt.multiplexed ? multiplexed_segments(index, mlt.max_depth) : 0,
                                   acceptance_stream(seed, c), {}, {}});
        }
        std::vector<ScratchArena> arenas(static_cast<std::size_t>(threads));
        const auto evaluate = [&](Chain& chain, ScratchArena& arena, ch04::SubpathStorage& storage, PathContributions& out) {
            if (chain.segments > 0)
                evaluate_multiplexed_path(scene, lights, bidirectional, chain.segments, chain.samples, arena, storage, out);
            else
                evaluate_path(scene, lights, bidirectional, chain.samples, arena, storage, out);
        };
        parallel_for(chain_count, threads, [&](std::size_t c, int thread) {
            thread_local ch04::SubpathStorage storage;
            Chain& chain = chains[c];
            evaluate(chain, arenas[static_cast<std::size_t>(thread)], storage, chain.current);
            chain.samples.set_random(mutation_stream(seed, c));
        });
        // END BOOK

        // BOOK(mutations)
        // A round is one mutation per pixel, spread over the chains; each chain records its
        // splats in its own buffer, added to the film in chain order (deterministic for any
        // thread count). Expected-value splatting (Veach 1997, section 11.3.3): both the proposal
        // and the current state are splatted, weighted by a and 1 - a, each as c b / I.
        std::vector<ch04::SplatBuffer> buffers(chain_count, ch04::SplatBuffer(width, height));
        const double b = bootstrap.b;
        while (rounds.next_batch(result)) {
            parallel_for(chain_count, threads, [&](std::size_t c, int thread) {
                thread_local ch04::SubpathStorage storage;
                Chain& chain = chains[c];
                ch04::SplatBuffer& buffer = buffers[c];
                buffer.clear();
                const std::uint64_t mutations = pixels / chain_count + (c < pixels % chain_count ? 1 : 0);
                for (std::uint64_t m = 0; m < mutations; ++m) {
                    chain.samples.start_iteration();
                    evaluate(chain, arenas[static_cast<std::size_t>(thread)], storage, chain.proposed);
                    chain.invalid += chain.proposed.invalid;
                    const float a = acceptance_probability(chain.current.value, chain.proposed.value);
                    // Half-buffers by chain: the chains are independent, the mutations of one are not.
                    buffer.begin_light_path(c);
                    if (a > 0.0f && chain.proposed.value > 0.0f)
                        for (const auto& splat : chain.proposed.splats)
                            buffer.add_splat(splat.raster_position, splat.value * static_cast<float>(a * b / chain.proposed.value));
                    if (a < 1.0f && chain.current.value > 0.0f)
                        for (const auto& splat : chain.current.splats)
                            buffer.add_splat(splat.raster_position,
                                             splat.value * static_cast<float>((1.0 - a) * b / chain.current.value));
                    ++chain.proposed_count;
                    if (chain.samples.large_step()) ++chain.large_proposed;
                    if (chain.acceptance.next_float() < a) {
                        ++chain.accepted_count;
                        if (chain.samples.large_step()) ++chain.large_accepted;
                        chain.samples.accept();
                        std::swap(chain.current, chain.proposed);
                    } else {
                        chain.samples.reject();
                    }
                }
                progress.advance(mutations);
            });
            for (const ch04::SplatBuffer& buffer : buffers) film.add(buffer);  // in chain order
            if (!rounds.batch_done(film, result)) break;
        }
        // END BOOK

        std::uint64_t proposed = 0, accepted = 0, large_proposed = 0, large_accepted = 0;
        for (const Chain& chain : chains) {
            proposed += chain.proposed_count;
            accepted += chain.accepted_count;
            large_proposed += chain.large_proposed;
            large_accepted += chain.large_accepted;
            result.invalid_samples += chain.invalid;
        }
        const auto rate = [](std::uint64_t a, std::uint64_t n) { return n > 0 ? 100.0 * a / n : 0.0; };
        result.notes.push_back(name + format(": acceptance %.1f %% of proposals (large steps %.1f %%, small steps %.1f %%)",
                                      rate(accepted, proposed), rate(large_accepted, large_proposed),
                                      rate(accepted - large_accepted, proposed - large_proposed)));
    }
    result.notes.push_back(name + format(": bootstrap b = %.6g +- %.2g (mean image luminance) from %.0f paths", bootstrap.b,
                                  bootstrap.standard_error, static_cast<double>(mlt.bootstrap_samples)));
    rounds.finish(film, result);
    return result;
}

}  // namespace freezeray::ch05
