// `auto`: pilots, the choice, and the rest of the render (see auto_integrator.hpp).
#include "freezeray/ch05/auto_integrator.hpp"

#include "freezeray/error.hpp"
#include "freezeray/progress.hpp"
#include "freezeray/agreement.hpp"
#include "freezeray/film.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/ch05/sds_probe.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

namespace freezeray::ch05 {

namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

// The result of a render from the film of pilot and rest merged (disjoint samples of one seed).
RenderResult merged_result(const RenderResult& pilot, RenderResult rest) {
    const Film merged = merge_films(*pilot.film, *rest.film);
    rest.image = merged.mean();
    rest.variance = merged.variance_of_mean();
    rest.samples_per_pixel = merged.minimum_sample_count();
    rest.estimated_relative_mse = merged.estimated_relative_mse();
    rest.invalid_samples += pilot.invalid_samples;
    rest.film = std::make_shared<const Film>(merged.clone());
    return rest;
}

}  // namespace

// BOOK(auto-choice)
IntegratorChoice choose_by_pilots(const std::vector<PilotMeasurement>& pilots) {
    // The most efficient qualified pilot; when none qualifies, the most efficient of all.
    IntegratorChoice choice;
    std::optional<std::size_t> best_qualified;
    std::size_t best_of_all = 0;
    for (std::size_t i = 0; i < pilots.size(); ++i) {
        if (pilots[i].efficiency > pilots[best_of_all].efficiency) best_of_all = i;
        if (pilots[i].disqualified.empty() && (!best_qualified || pilots[i].efficiency > pilots[*best_qualified].efficiency))
            best_qualified = i;
    }
    const bool any_qualified = best_qualified.has_value();
    choice.chosen = best_qualified.value_or(best_of_all);
    const PilotMeasurement& best = pilots[choice.chosen];
    choice.reason = best.integrator + ": estimated efficiency " + number(best.efficiency) + " per second";
    if (!any_qualified)
        choice.reason += ", the highest, but no candidate's estimate could be trusted, its own neither (" +
                         best.disqualified + "): a guess";
    for (const PilotMeasurement& other : pilots) {
        if (&other == &best) continue;
        if (!other.disqualified.empty())
            choice.reason += "; " + other.integrator + " left out: " + other.disqualified;
        else if (other.efficiency > 0.0)
            choice.reason += "; " + number(best.efficiency / other.efficiency) + "x that of " + other.integrator;
    }
    return choice;
}
// END BOOK

RenderResult AutoIntegrator::render(const Scene& scene, const RenderSettings& settings, Progress& progress) const {
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    if (settings.resume)
        throw InputError("--resume", "auto's choice is part of its render: resume with the --integrator it chose");

    // The candidates the scene allows: only those that sample lights find point, spot and
    // directional lights, which no ray can hit.
    std::vector<const Candidate*> usable;
    for (const Candidate& c : candidates_)
        if (!scene.effects.delta_lights || c.traits.samples_lights) usable.push_back(&c);
    if (usable.empty()) throw InputError("--integrator", "auto has no candidate that can render this scene's lights");

    // BOOK(auto-sds)
    // Specular-diffuse-specular paths (sds_probe.hpp): where they light more than SdsShareLimit
    // of the image, the candidates that sample every path from scratch have a tail of rare, very
    // bright samples that their pilots seldom meet and so cannot measure. The chains, which
    // explore such a path once found, are kept, if there are any; else every estimate may miss
    // that tail, and the render says so.
    std::string left_out_before_pilots;
    std::string probe_note;  // what the probe measured and took, for the note
    std::vector<std::string> warnings;
    if (scene.effects.specular) {
        SdsProbeSettings probe;
        probe.seed = settings.seed;
        probe.threads = settings.threads;
        const SdsShare sds = measure_sds_share(scene, settings.light_sampler.get(), probe);
        probe_note = "; SDS probe " + number(sds.share) + " of the image, " + number(elapsed()) + " s";
        if (sds.share > SdsShareLimit) {
            const std::string why = number(sds.share) +
                                    " of the image is lit through a specular surface and seen through one, light that only "
                                    "a camera path hitting the light carries: a tail of rare bright samples no pilot measures";
            std::vector<const Candidate*> chains;
            for (const Candidate* c : usable)
                if (c->traits.explores_found_paths) chains.push_back(c);
            if (!chains.empty() && chains.size() < usable.size()) {
                for (const Candidate* c : usable)
                    if (!c->traits.explores_found_paths)
                        left_out_before_pilots += (left_out_before_pilots.empty() ? "" : ", ") + c->name;
                left_out_before_pilots += " left out before the pilots: " + why;
                usable = chains;
            } else if (chains.empty()) {
                warnings.push_back("auto: " + why + "; no candidate here explores the paths it finds (mlt does, from "
                                   "chapter 05 on), so the pilots' estimates may be far too low");
            }
        }
    }
    // END BOOK

    // A choice of one needs no pilot: the candidate renders the whole budget.
    if (usable.size() == 1) {
        const Candidate& only = *usable.front();
        RenderSettings whole = settings;
        if (!only.traits.draws_from_sampler) whole.sampler = nullptr;
        RenderResult result = only.integrator->render(scene, whole, progress);
        result.seconds = elapsed();
        result.integrator = only.name;
        result.integrator_choice = only.name + ": the only candidate" +
                                   (left_out_before_pilots.empty() ? std::string(" this scene allows") : "; " + left_out_before_pilots);
        result.notes.insert(result.notes.begin(), "auto chose " + result.integrator_choice + " (no pilots" + probe_note + ")");
        result.warnings.insert(result.warnings.end(), warnings.begin(), warnings.end());
        return result;
    }

    // The pilots: PilotSamples per pixel with each, quietly, their error estimate at every pass.
    std::vector<PilotMeasurement> pilots;
    std::vector<RenderResult> results;
    for (const Candidate* c : usable) {
        RenderSettings pilot_settings = settings;
        pilot_settings.samples_per_pixel = PilotSamples;
        pilot_settings.time_seconds = 0.0;
        pilot_settings.target_error = 0.0;
        pilot_settings.max_pass_seconds = 0.0;
        pilot_settings.sampler = nullptr;  // independent: the variance estimates must be honest
        std::vector<std::pair<std::uint64_t, double>> estimates;
        pilot_settings.on_pass = [&](const Film& film, std::uint64_t spp, double) {
            estimates.emplace_back(spp, film.estimated_relative_mse());
        };
        Progress quiet(true);
        RenderResult r = c->integrator->render(scene, pilot_settings, quiet);
        if (r.interrupted) {
            r.integrator = c->name;
            r.integrator_choice = "interrupted during the pilots";
            return r;
        }
        PilotMeasurement m;
        m.integrator = c->name;
        m.seconds = r.seconds;
        m.samples_per_pixel = r.samples_per_pixel;
        m.estimated_relative_mse = r.estimated_relative_mse;
        if (m.estimated_relative_mse > 0.0 && std::isfinite(m.estimated_relative_mse) && m.seconds > 0.0)
            m.efficiency = 1.0 / (m.estimated_relative_mse * m.seconds);
        double at_half = -1.0;  // the estimate at half the pilot's samples
        for (const auto& [spp, estimate] : estimates)
            if (2 * spp == r.samples_per_pixel) at_half = estimate;
        if (m.efficiency <= 0.0)
            m.disqualified = "no error estimate";
        else if (at_half > 0.0 && m.estimated_relative_mse >= RisingTolerance * at_half)
            m.disqualified = "its estimated error rose from " + number(at_half) + " to " + number(m.estimated_relative_mse) +
                             " as samples were added (rare bright paths still being found)";
        pilots.push_back(m);
        results.push_back(std::move(r));
    }
    // A pilot whose image disagrees with every other's far more than those disagree among
    // themselves (odd_one_out) has not found light they found, or is biased: its estimate is too low.
    std::vector<const RenderResult*> images;
    for (const RenderResult& r : results) images.push_back(&r);
    if (const std::optional<std::size_t> odd = odd_one_out(pairwise_agreements(images), results.size());
        odd && pilots[*odd].disqualified.empty())
        pilots[*odd].disqualified = "its image disagrees with the other pilots' far more than they disagree among "
                                    "themselves (light it has not found yet)";
    IntegratorChoice choice = choose_by_pilots(pilots);
    if (!left_out_before_pilots.empty()) choice.reason += "; " + left_out_before_pilots;
    const Candidate& chosen = *usable[choice.chosen];
    RenderResult& pilot = results[choice.chosen];
    double pilots_seconds = 0.0;
    for (const PilotMeasurement& m : pilots) pilots_seconds += m.seconds;
    const std::string note = "auto chose " + choice.reason + " (pilots of " + std::to_string(PilotSamples) +
                             " spp each, " + number(pilots_seconds) + " s in all" + probe_note + ")";

    // The rest of the budget, with the chosen pilot's samples kept.
    RenderSettings rest = settings;
    bool done = false;
    const double spent = elapsed();
    if (settings.time_seconds > 0.0) {
        rest.time_seconds = settings.time_seconds - spent;
        done = rest.time_seconds <= 0.0;
    } else if (settings.target_error > 0.0) {
        done = pilot.estimated_relative_mse > 0.0 && pilot.estimated_relative_mse <= settings.target_error;
    } else {
        done = pilot.samples_per_pixel >= settings.samples_per_pixel;
    }
    RenderResult result;
    if (done) {
        result = std::move(pilot);
    } else if (chosen.traits.resumable && !(settings.sampler && chosen.traits.draws_from_sampler)) {
        // Every pixel goes on from the pilot's samples: the same image as a render of the whole
        // budget with the chosen integrator from the start.
        rest.resume = pilot.film;
        if (settings.on_pass)
            rest.on_pass = [&](const Film& film, std::uint64_t spp, double seconds) { settings.on_pass(film, spp, seconds + spent); };
        result = chosen.integrator->render(scene, rest, progress);
    } else {
        // A film that cannot be continued, or a pilot drawn from another sampler than the rest's
        // (independent, then Sobol): the rest renders the next sample indices of the same seed
        // with the render's sampler, and the two are merged, as `merge` does.
        if (!chosen.traits.draws_from_sampler) rest.sampler = nullptr;
        rest.first_sample = settings.first_sample + pilot.samples_per_pixel;
        if (settings.time_seconds <= 0.0 && settings.target_error <= 0.0)
            rest.samples_per_pixel = settings.samples_per_pixel - pilot.samples_per_pixel;
        if (settings.on_pass)
            rest.on_pass = [&](const Film& film, std::uint64_t spp, double seconds) {
                settings.on_pass(merge_films(*pilot.film, film), spp + pilot.samples_per_pixel, seconds + spent);
            };
        result = merged_result(pilot, chosen.integrator->render(scene, rest, progress));
    }
    result.seconds = elapsed();
    result.integrator = chosen.name;
    result.integrator_choice = choice.reason;
    result.notes.insert(result.notes.begin(), note);
    result.warnings.insert(result.warnings.end(), warnings.begin(), warnings.end());
    return result;
}

void register_auto_integrator(Registry& registry, int chapter) {
    std::vector<std::pair<std::string, IntegratorFactory>> factories;
    for (const char* name : {"pt-mis", "bdpt", "mlt"})
        if (const IntegratorFactory* factory = registry.integrators.find(name)) factories.emplace_back(name, *factory);
    // What auto is: what any of its candidates is. The render's light sampler reaches the
    // candidates that choose lights per point, and its sampler the chosen candidate's rest of the
    // budget when that one draws from it (the pilots always use the independent sampler: their
    // error is estimated from the per-pixel variance, honest only for independent samples,
    // chapter 09). The choice is part of the render, so it cannot be resumed.
    IntegratorTraits traits{.resumable = false};
    for (const auto& [name, factory] : factories) {
        traits.samples_lights |= factory.traits.samples_lights;
        traits.draws_from_sampler |= factory.traits.draws_from_sampler;
        traits.chooses_lights_per_point |= factory.traits.chooses_lights_per_point;
    }
    registry.integrators.add("auto", chapter,
                            "the integrator chosen by measurement: short pilots with pt-mis, bdpt and mlt, the most "
                            "efficient one whose error estimate can be trusted renders the rest",
                            {traits, [factories](const RenderSettings& settings, const Parameters& options) {
                                 std::vector<AutoIntegrator::Candidate> candidates;
                                 for (const auto& [name, factory] : factories)
                                     candidates.push_back({name, factory.traits, factory(settings, options)});
                                 return std::make_unique<AutoIntegrator>(std::move(candidates));
                             }});
}

}  // namespace freezeray::ch05
