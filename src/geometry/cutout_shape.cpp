#include "glint/geometry/cutout_shape.h"

#include <cmath>

namespace glint {

namespace {

/// Most cut hits stepped over along one ray: a heightfield seen edge-on can fold many times,
/// but a ray that meets this many holes in a row is treated as passing through.
constexpr int kMaxSteps = 256;

}  // namespace

bool CutoutShape::intersect(Ray& ray, Hit& hit) const {
    Ray probe = ray;
    for (int step = 0; step < kMaxSteps; ++step) {
        Hit candidate;
        if (!shape_->intersect(probe, candidate)) return false;
        SurfaceInteraction si;
        shape_->interaction(probe, candidate, si);
        if (alpha_->alpha(si.uv) >= cutoff_) {
            ray.tmax = candidate.t;
            hit = candidate;
            return true;
        }
        // Go on from the next float past the cut hit: [tmin, tmax] is inclusive, and the
        // same hit recomputed from the same ray lands on the same t.
        probe.tmin = std::nextafter(candidate.t, ray.tmax + 1.0f);
        probe.tmax = ray.tmax;
        if (!(probe.tmin <= probe.tmax)) return false;
    }
    return false;
}

bool CutoutShape::occluded(const Ray& ray) const {
    Ray probe = ray;
    Hit hit;
    return intersect(probe, hit);
}

}  // namespace glint
