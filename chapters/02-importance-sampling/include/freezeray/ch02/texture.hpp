// Textures: a material parameter that varies over a surface, looked up by texture coordinates.
// A parameter that does not vary is a ConstantTexture, so materials treat both alike.
#pragma once

#include "freezeray/math.hpp"
#include "freezeray/texture_storage.hpp"

#include <memory>

namespace freezeray::ch02 {

// A value of type T (float or Spectrum) for every point (u, v) of texture space.
template <typename T>
class Texture {
public:
    virtual ~Texture() = default;

    // The value at texture coordinates lookup.uv, (0, 0) the bottom-left corner of an image as in
    // OBJ, filtered over the pixel's footprint when the texture can (chapter 08's MIP maps).
    virtual T eval(const TextureLookup& lookup) const = 0;

    // True when eval returns the same value everywhere (no texture fetch is ever needed).
    virtual bool is_constant() const { return false; }

    // Bounds of every value eval can return (per channel for a Spectrum): what a material
    // checks a texture against, and how it knows, for instance, whether a roughness map can
    // make a surface smooth somewhere.
    virtual T minimum() const = 0;
    virtual T maximum() const = 0;
};

// The same value everywhere: how a parameter given as a plain number or colour is stored.
template <typename T>
class ConstantTexture final : public Texture<T> {
public:
    explicit ConstantTexture(const T& value) : value_(value) {}

    T eval(const TextureLookup& /*lookup*/) const override { return value_; }
    bool is_constant() const override { return true; }
    T minimum() const override { return value_; }
    T maximum() const override { return value_; }

    const T& value() const { return value_; }

private:
    T value_;
};

// Materials share textures (a mix material and its parts, two materials naming one file).
using FloatTexture = std::shared_ptr<const Texture<float>>;
using SpectrumTexture = std::shared_ptr<const Texture<Spectrum>>;

// A shared constant texture holding `value`.
template <typename T>
std::shared_ptr<const Texture<T>> make_constant_texture(const T& value) {
    return std::make_shared<ConstantTexture<T>>(value);
}

}  // namespace freezeray::ch02
