// Which integrator suits a scene: `info`'s suggestion and `render`'s integrator when neither the
// command line nor the scene names one. The knowledge is the chapters': each adds a rule for the
// integrator it teaches (chapter 03: its path tracer wherever there is light; chapter 04:
// bidirectional path tracing where caustics are lit; chapter 05: the Markov chain where a probe
// finds specular-diffuse-specular paths), and the rules of later chapters are asked first.
// common/ names no integrator.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace freezeray {

class LightSampler;
class Registry;
class Scene;

// An integrator suited to a scene: its registered name (empty when none fits) and why.
struct IntegratorAdvice {
    std::string name;
    std::string reason;
};

// What a rule may use and give back besides its verdict.
struct AdviceRequest {
    // `info` asks for everything a rule can measure and say; `render` only for its choice.
    bool detailed = false;
    // How the render would choose lights (may be null: uniformly).
    const LightSampler* lights = nullptr;
    // Lines a rule adds for `info`: what it measured to decide.
    std::vector<std::string>* notes = nullptr;
};

// A chapter's rule: the reason its integrator suits `scene`, or nothing when it does not.
struct AdviceRule {
    std::string integrator;
    std::function<std::optional<std::string>(const Scene& scene, const AdviceRequest& request)> applies;
    // It traces rays through the scene to decide (chapter 05's probe): the scene's accelerator
    // must be built first (`info` builds it only then).
    bool traces_rays = false;
};

// The first rule, the last registered first, whose integrator the registry has and that applies
// to the scene; for a scene without light, none (it renders black), and where no rule applies,
// none with the reason that light sampling is missing.
IntegratorAdvice advise_integrator(const Scene& scene, const Registry& registry, const AdviceRequest& request = {});

}  // namespace freezeray
