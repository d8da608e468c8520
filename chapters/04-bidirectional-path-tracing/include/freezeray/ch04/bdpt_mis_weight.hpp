// The multiple importance sampling weight of one bidirectional strategy (s, t) against every
// other strategy that could have made the same path (Veach 1997, section 10.3; Veach and Guibas
// 1995; pbrt-v3, section 16.3.4), computed from the densities stored along the subpaths so that
// its cost grows with the path's length, not with its square.
#pragma once

#include "freezeray/ch03/mis.hpp"
#include "freezeray/ch04/path_vertex.hpp"

namespace freezeray::ch04 {

// One step of the ratio recurrence r_{i} = r_{i+1} p_rev / p_fwd (Veach 1997, eq. 10.9): the
// density with which the neighbouring strategy makes vertex i, over the density with which
// this one does. A zero density (a delta lobe, which the weight then skips) counts as 1 so that
// the product stays finite.
double next_strategy_ratio(double ratio, float pdf_reverse, float pdf_forward);

// The weight of strategy (s, t) for the path light[0 .. s) + camera[t-1 .. 0]. `sampled`
// replaces light[s-1] when s = 1 or camera[t-1] when t = 1 (a vertex sampled by the
// connection; null otherwise). The subpaths' reverse densities at the connection are
// recomputed here (they depend on the other subpath) without changing the arrays.
// Only strategies that this chapter's bdpt implements are counted (s = 1, t = 1 only for area
// lights), so the weights of every strategy of one path sum to one.
float bdpt_mis_weight(const Scene& scene, const ch03::FixedLightSampler& lights, ch03::MisHeuristic heuristic,
                      const PathVertex* light, int s, const PathVertex* camera, int t, const PathVertex* sampled);

}  // namespace freezeray::ch04
