#pragma once
/// \file What a ray's traversal cost: the viewer's heatmaps count BVH nodes visited and
/// primitives tested. The traversals take a counting policy as a template parameter, so the
/// render's own traversals (NoTraversalCount) compile exactly as without it.

#include <cstdint>

namespace glint {

struct TraversalStats {
    /// Nodes whose children's boxes were tested (binary top level and 8-wide mesh nodes).
    uint64_t nodes = 0;
    /// Primitives tested: triangles (each real triangle of a leaf block) and analytic shapes.
    uint64_t primitives = 0;
};

/// Counts nothing, at no cost.
struct NoTraversalCount {
    void node() const {}
    void primitives(uint64_t) const {}
};

/// Counts into `stats`.
struct TraversalCount {
    TraversalStats* stats;
    void node() const { ++stats->nodes; }
    void primitives(uint64_t n) const { stats->primitives += n; }
};

}  // namespace glint
