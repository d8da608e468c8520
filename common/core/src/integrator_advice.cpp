// Which integrator suits a scene, from the chapters' rules.
#include "freezeray/integrator_advice.hpp"

#include "freezeray/registry.hpp"
#include "freezeray/scene.hpp"

namespace freezeray {

IntegratorAdvice advise_integrator(const Scene& scene, const Registry& registry, const AdviceRequest& request) {
    const SceneEffects& effects = scene.effects;
    if (!effects.area_emitters && !effects.environment && !effects.delta_lights)
        return {"", "the scene has no light and renders black"};
    const std::vector<AdviceRule>& rules = registry.advice_rules();
    for (auto rule = rules.rbegin(); rule != rules.rend(); ++rule) {
        if (!registry.has(CapabilityKind::Integrator, rule->integrator)) continue;
        if (const std::optional<std::string> reason = rule->applies(scene, request)) return {rule->integrator, *reason};
    }
    return {"", "point, spot and directional lights are found only by light sampling, which comes in chapter 03"};
}

}  // namespace freezeray
