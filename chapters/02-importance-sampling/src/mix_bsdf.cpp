// The blend of two BSDFs, sampled as a one-sample mixture (Veach 1997, section 9.2.4: choosing one
// strategy at random, with the combined density).
#include "freezeray/ch02/mix_bsdf.hpp"

#include <algorithm>

namespace freezeray::ch02 {

Spectrum MixBSDF::eval(const Vec3& wo, const Vec3& wi) const {
    return (1.0f - weight_) * first_->eval(wo, wi) + weight_ * second_->eval(wo, wi);
}

float MixBSDF::pdf(const Vec3& wo, const Vec3& wi) const {
    return (1.0f - weight_) * first_->pdf(wo, wi) + weight_ * second_->pdf(wo, wi);
}

// Pick `second` with probability weight, reusing u_lobe: the part of [0, 1) that chose a
// component, stretched back to [0, 1), is again uniform, and lets that component pick its own
// lobe. A non-delta sample could have come from either component, so its density is the mixture
// pdf and its f the blended f. A delta sample exists only in its component: its f and
// probability are that component's, both scaled by the probability of the choice.
std::optional<BSDFSample> MixBSDF::sample(const Vec3& wo, const Vec2& u, float u_lobe) const {
    const bool pick_second = u_lobe < weight_;
    const float probability = pick_second ? weight_ : 1.0f - weight_;
    const float u_remapped = pick_second ? u_lobe / weight_ : (u_lobe - weight_) / (1.0f - weight_);
    const BSDF* chosen = pick_second ? second_ : first_;
    std::optional<BSDFSample> s = chosen->sample(wo, u, std::min(u_remapped, 0x1.fffffep-1f));
    if (!s) return std::nullopt;
    if (has_flag(s->flags, BSDF_Specular)) {
        s->f *= probability;
        s->pdf *= probability;
        return s;
    }
    s->f = eval(wo, s->wi);
    s->pdf = pdf(wo, s->wi);
    if (!(s->pdf > 0.0f)) return std::nullopt;
    return s;
}

std::uint32_t MixBSDF::flags() const {
    if (weight_ <= 0.0f) return first_->flags();
    if (weight_ >= 1.0f) return second_->flags();
    return first_->flags() | second_->flags();
}

}  // namespace freezeray::ch02
