// Joint sets: which draws of a pixel sample a quasi-Monte Carlo sampler stratifies together (book
// chapter 09, "Drawing jointly"). The dimensions themselves are common/'s (sampler.hpp: every
// per-pixel integrator from chapter 02 on draws by them); which set each draw joins, and its
// coordinate there, is this chapter's lesson, read by its samplers.
#pragma once

#include "freezeray/sampler.hpp"

#include <cstdint>

namespace freezeray::ch09 {

// Where a draw sits among a pixel sample's numbers. Every draw has its own dimension. It also
// belongs to a joint set: a quasi-Monte Carlo sampler gives the draws of one set as coordinates of
// one point of its sequence, so that they are stratified together, not only each on its own, and
// draws of different sets independently of each other (book chapter 09, "Drawing jointly"). A
// set is named by its first dimension. Samplers that stratify nothing jointly (independent,
// stratified) read the dimension only.
struct DrawPlace {
    std::uint32_t dimension;   // the draw's (a pair's: dimension and dimension + 1)
    std::uint32_t set;         // the first dimension of the draw's joint set
    std::uint32_t coordinate;  // the draw's in the set's point (a pair's: coordinate and coordinate + 1)
    friend constexpr bool operator==(const DrawPlace&, const DrawPlace&) = default;
};
// The most coordinates a joint set's points have.
constexpr std::uint32_t MaxJointCoordinates = 15;

// The path set: from vertex 1's BSDF sample, every draw up to vertex JointPathVertices's BSDF
// sample is one point. Light reaching the camera after a bounce is a function of vertex 1's BSDF
// direction and of the next vertex's light sample together: stratified jointly, the points of
// the second cover the light from every stratum of the first (book chapter 09, "Drawing jointly").
constexpr int JointPathVertices = 3;
constexpr std::uint32_t PathSet = CameraDimensions + static_cast<std::uint32_t>(VertexDimension::BsdfDirection);

// A draw's place in the per-vertex layout:
// - vertex 1 to JointPathVertices: their BSDF draws and the light draws of vertices 2 on are in
//   the path set, at the coordinates of the table below; vertex 1's light sample is a set of its
//   own (position: coordinates 0 and 1, choice: 2), drawn jointly so that the samples that choose
//   one light still cover it evenly;
// - deeper vertices: the light sample is a set (position 0 and 1, choice 2), the BSDF sample is
//   one (direction 0 and 1, lobe 2);
// - Russian roulette is always a set of its own.
// A set's coordinates are numbered by importance: vertex 1's direction first, then vertex 2's
// light sample, whose light depends on it most. A quasi-Monte Carlo sampler gives the first
// coordinates its best-stratified dimensions (chapter 09's JointCoordinateDimension).
constexpr DrawPlace vertex_draw_place(int vertex, VertexDimension d) {
    const std::uint32_t first = CameraDimensions + DimensionsPerVertex * static_cast<std::uint32_t>(vertex - 1);
    const std::uint32_t dimension = vertex_draw(vertex, d).dimension;
    const std::uint32_t light_set = first + static_cast<std::uint32_t>(VertexDimension::LightPosition);
    const std::uint32_t bsdf_set = first + static_cast<std::uint32_t>(VertexDimension::BsdfDirection);
    // Path-set coordinates of vertices 1 to 3: light position, light choice, BSDF direction,
    // BSDF lobe (vertex 1's light entries are not used: its light sample is a set of its own).
    constexpr std::uint32_t path_coordinates[JointPathVertices][4] = {{0, 0, 0, 12}, {2, 6, 4, 13}, {7, 11, 9, 14}};
    const bool in_path = vertex >= 1 && vertex <= JointPathVertices;
    const std::uint32_t* path = in_path ? path_coordinates[vertex - 1] : nullptr;
    switch (d) {
        case VertexDimension::LightPosition:
            return in_path && vertex > 1 ? DrawPlace{dimension, PathSet, path[0]} : DrawPlace{dimension, light_set, 0};
        case VertexDimension::LightChoice:
            return in_path && vertex > 1 ? DrawPlace{dimension, PathSet, path[1]} : DrawPlace{dimension, light_set, 2};
        case VertexDimension::BsdfDirection:
            return in_path ? DrawPlace{dimension, PathSet, path[2]} : DrawPlace{dimension, bsdf_set, 0};
        case VertexDimension::BsdfLobe:
            return in_path ? DrawPlace{dimension, PathSet, path[3]} : DrawPlace{dimension, bsdf_set, 2};
        case VertexDimension::Roulette: break;
    }
    return DrawPlace{dimension, dimension, 0};
}

// The place of any draw: a per-vertex draw's as above; any other (the position in the pixel, a
// dimension an integrator lays out itself) is a set of its own.
constexpr DrawPlace draw_place(const Draw& draw) {
    return draw.vertex > 0 ? vertex_draw_place(draw.vertex, draw.role) : DrawPlace{draw.dimension, draw.dimension, 0};
}

}  // namespace freezeray::ch09
