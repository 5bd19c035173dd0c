#pragma once
/// \file The binning arithmetic of the SAH builder (sah_builder.cpp): boxes of four lanes,
/// primitive references, the bins of the three axes and the mapping of centroids to bins.
/// Internal to src/accel.

#include "glint/math/bounds3.h"

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <utility>

namespace glint::sah {

/// The most bins per axis (BvhBuildConfig::bin_count): a mask of 64 bits marks the used ones.
constexpr uint32_t kMaxBins = 64;

/// A box as one row of eight floats: its low corner (x, y, z and a spare lane), then its
/// high corner negated (the same). Extending one box by another is then a single min of
/// eight lanes, where Bounds3 takes six scalar steps and a row for each corner took a min
/// and a max of four: binning is most of the build (Wald 2007 bins with SSE the same way).
/// Lane by lane the results are Bounds3's bit for bit: min(−a, −b) = −max(a, b) exactly, and
/// on ties and NaN min and max keep the same operand, so the tree is the one the scalar code
/// built.
struct alignas(32) Box4 {
    /// lo.x, lo.y, lo.z, spare, −hi.x, −hi.y, −hi.z, spare.
    float v[8];

    /// The empty box (lo > hi), which extending by anything makes that thing.
    [[nodiscard]] static Box4 empty() {
        return {{kInfinity, kInfinity, kInfinity, kInfinity, kInfinity, kInfinity, kInfinity, kInfinity}};
    }

    void extend(const Box4& b) {
#if defined(__AVX__)
        // minps(a, b) is a < b ? a : b, so minps(new, old) is std::min(old, new).
        _mm256_storeu_ps(v, _mm256_min_ps(_mm256_loadu_ps(b.v), _mm256_loadu_ps(v)));
#elif defined(__SSE2__)
        _mm_storeu_ps(v, _mm_min_ps(_mm_loadu_ps(b.v), _mm_loadu_ps(v)));
        _mm_storeu_ps(v + 4, _mm_min_ps(_mm_loadu_ps(b.v + 4), _mm_loadu_ps(v + 4)));
#else
        for (int i = 0; i < 8; ++i) v[i] = std::min(v[i], b.v[i]);
#endif
    }
    /// Extend by the point in the first three lanes of `p`.
    void extend_point(const float* p) { extend(point(p)); }
    /// Extend by the point in the first three lanes of `p` if `yes`, without a branch.
    void extend_point_if(const float* p, bool yes) {
#if defined(__AVX__)
        // Where `yes` is false the point is replaced by the box itself, which leaves it as it is.
        const __m128 q = _mm_loadu_ps(p);
        const __m256 row = _mm256_insertf128_ps(_mm256_castps128_ps256(q), _mm_xor_ps(q, _mm_set1_ps(-0.0f)), 1);
        const __m256 take = _mm256_castsi256_ps(_mm256_set1_epi32(-int32_t(yes)));
        const __m256 box = _mm256_loadu_ps(v);
        _mm256_storeu_ps(v, _mm256_min_ps(_mm256_blendv_ps(box, row, take), box));
#elif defined(__SSE2__)
        const __m128 take = _mm_castsi128_ps(_mm_set1_epi32(-int32_t(yes)));
        const __m128 q = _mm_loadu_ps(p), negated = _mm_xor_ps(q, _mm_set1_ps(-0.0f));
        const __m128 lo = _mm_loadu_ps(v), neg_hi = _mm_loadu_ps(v + 4);
        _mm_storeu_ps(v, _mm_min_ps(_mm_or_ps(_mm_and_ps(take, q), _mm_andnot_ps(take, lo)), lo));
        _mm_storeu_ps(v + 4, _mm_min_ps(_mm_or_ps(_mm_and_ps(take, negated), _mm_andnot_ps(take, neg_hi)), neg_hi));
#else
        if (yes) extend_point(p);
#endif
    }
    [[nodiscard]] Bounds3 bounds() const { return {{v[0], v[1], v[2]}, {-v[4], -v[5], -v[6]}}; }
    /// Bounds3::half_area of a box that is not empty, by the same sum of products in the same
    /// order, without the conversion to Bounds3 and the emptiness test the split search paid
    /// for each bin (the trees it builds hash the same as before, docs/performance.md).
    [[nodiscard]] float half_area() const {
        alignas(16) float d[4];
#if defined(__SSE2__)
        const __m128 hi = _mm_xor_ps(_mm_loadu_ps(v + 4), _mm_set1_ps(-0.0f));
        _mm_store_ps(d, _mm_sub_ps(hi, _mm_loadu_ps(v)));
#else
        for (int i = 0; i < 4; ++i) d[i] = -v[4 + i] - v[i];
#endif
        return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
    }

private:
    /// The box of the point in the first four lanes of `p`.
    [[nodiscard]] static Box4 point(const float* p) {
        Box4 b;
        for (int i = 0; i < 4; ++i) {
            b.v[i] = p[i];
            b.v[4 + i] = -p[i];
        }
        return b;
    }
};

/// A primitive's box and index in 32 bytes, the index in the spare lane of the low corner (as
/// Embree's PrimRef keeps it); that lane's min and max in the bins mean nothing, and no
/// arithmetic reads it (an index's bits are mostly a denormal float, which would slow an
/// addition down many times over).
struct PrimRef {
    Box4 box;
    /// Unwritten, for arrays filled right after (UninitializedArray).
    PrimRef() = default;
    PrimRef(const Bounds3& b, uint32_t id) : box() {
        for (int a = 0; a < 3; ++a) {
            box.v[a] = b.lo[a];
            box.v[4 + a] = -b.hi[a];
        }
        std::memcpy(&box.v[3], &id, sizeof id);
        box.v[7] = 0.0f;
    }
    [[nodiscard]] uint32_t id() const {
        uint32_t id = 0;
        std::memcpy(&id, &box.v[3], sizeof id);
        return id;
    }
    /// (lo + hi)/2, as lo − (−hi): the same sum, bit for bit.
    [[nodiscard]] float centroid(int axis) const { return 0.5f * (box.v[axis] - box.v[4 + axis]); }
    /// The centroid in the first three lanes, 0 in the fourth.
    void centroid(float* out) const {
#if defined(__SSE2__)
        const __m128 xyz = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
        const __m128 lo = _mm_and_ps(_mm_loadu_ps(box.v), xyz);
        _mm_store_ps(out, _mm_mul_ps(_mm_sub_ps(lo, _mm_loadu_ps(box.v + 4)), _mm_set1_ps(0.5f)));
#else
        for (int i = 0; i < 3; ++i) out[i] = 0.5f * (box.v[i] - box.v[4 + i]);
        out[3] = 0.0f;
#endif
    }
};
static_assert(sizeof(PrimRef) == 32);

/// Exchanges two references (which may be the same), each moved whole: one 32-byte load and
/// one 32-byte store. The partition swaps at every primitive, and a primitive that stays
/// put is loaded again by the next swap; copied as a struct, it had been stored as two
/// 16-byte halves, which the CPU cannot forward to one 32-byte load: 13 % of the split
/// search's samples sat on that stall (docs/performance.md).
inline void swap_refs(PrimRef& a, PrimRef& b) {
#if defined(__AVX__)
    const __m256 a_whole = _mm256_loadu_ps(a.box.v), b_whole = _mm256_loadu_ps(b.box.v);
    _mm256_storeu_ps(a.box.v, b_whole);
    _mm256_storeu_ps(b.box.v, a_whole);
#else
    std::swap(a, b);
#endif
}

/// The range's box and the box of its primitives' centroids.
struct RangeBounds {
    Box4 bounds = Box4::empty(), centroids = Box4::empty();
    void add(const PrimRef& r) {
        bounds.extend(r.box);
        alignas(16) float c[4];
        r.centroid(c);
        centroids.extend_point(c);
    }
    void merge(const RangeBounds& o) {
        bounds.extend(o.bounds);
        centroids.extend(o.centroids);
    }
};

/// The bins of the three axes. Only the first `used` of each are set: most ranges are
/// small, and clearing all 64 bins of every axis for each was a tenth of the build. Counts
/// are set up to the next multiple of four, so that nonempty() reads them four at a time.
class Bins {
public:
    explicit Bins(uint32_t used) : used_(used) {
        for (int a = 0; a < 3; ++a) {
            for (uint32_t b = 0; b < used; ++b) {
                bounds[a][b] = Box4::empty();
                count[a][b] = 0;
            }
            for (uint32_t b = used; b < counted(); ++b) count[a][b] = 0;
        }
    }
    Bins(const Bins& o) : used_(o.used_) { *this = o; }
    Bins& operator=(const Bins& o) {
        used_ = o.used_;
        for (int a = 0; a < 3; ++a) {
            std::copy_n(o.bounds[a], used_, bounds[a]);
            std::copy_n(o.count[a], counted(), count[a]);
        }
        return *this;
    }
    void merge(const Bins& o) {
        for (int a = 0; a < 3; ++a)
            for (uint32_t b = 0; b < used_; ++b) {
                bounds[a][b].extend(o.bounds[a][b]);
                count[a][b] += o.count[a][b];
            }
    }

    /// Bit b is set when bin b of `axis` holds primitives: the sweep visits only those, and
    /// finding them four counts at a time was a sixth of the split search when it tested
    /// every bin of every node one by one (most nodes hold a few primitives).
    [[nodiscard]] uint64_t nonempty(int axis) const {
        uint64_t mask = 0;
#if defined(__SSE2__)
        for (uint32_t b = 0; b < used_; b += 4) {
            const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(count[axis] + b));
            const int empty = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(c, _mm_setzero_si128())));
            mask |= uint64_t(~empty & 0xf) << b;
        }
#else
        for (uint32_t b = 0; b < used_; ++b) mask |= uint64_t(count[axis][b] != 0) << b;
#endif
        return mask;
    }

    /// The union of the boxes of `axis`'s bins whose bits `mask` sets (nonempty() or a part
    /// of it), taken in bin order. Children's boxes come from the bins this way: testing
    /// every bin's count instead mispredicted at random and cost 9 % of the binary build.
    [[nodiscard]] Box4 union_of(int axis, uint64_t mask) const {
        Box4 u = Box4::empty();
        for (; mask != 0; mask &= mask - 1) u.extend(bounds[axis][std::countr_zero(mask)]);
        return u;
    }

    // Boxes are left uninitialised past `used`, counts past counted() (copying them would
    // read indeterminate values).
    Box4 bounds[3][kMaxBins];
    alignas(16) uint32_t count[3][kMaxBins];

private:
    /// How many counts are set: `used` rounded up to a multiple of four.
    [[nodiscard]] uint32_t counted() const { return (used_ + 3) & ~3u; }

    uint32_t used_;
};

/// Maps a centroid coordinate to its bin; the scale leaves the last bin reachable only
/// by the maximum, and the clamp guards against rounding.
struct BinMapping {
    alignas(16) float lo[4] = {};
    alignas(16) float scale[4] = {};
    uint32_t bins;
    BinMapping(const Bounds3& centroids, uint32_t bin_count) : bins(bin_count) {
        const Vec3 extent = centroids.diagonal();
        for (int a = 0; a < 3; ++a) {
            lo[a] = centroids.lo[a];
            scale[a] = extent[a] > 0.0f ? float(bin_count) * 0.99999f / extent[a] : 0.0f;
        }
    }
    /// The bins of a primitive's centroid along the three axes (the fourth is 0), the same
    /// numbers for binning and for the partition that follows it.
    [[nodiscard]] std::array<uint32_t, 4> bins_of(const PrimRef& r) const {
        alignas(16) float centroid[4];
        r.centroid(centroid);
        return bins_of_centroid(centroid);
    }
    /// The same for a centroid already computed (PrimRef::centroid, 16-byte aligned).
    [[nodiscard]] std::array<uint32_t, 4> bins_of_centroid(const float* centroid) const {
        alignas(16) std::array<uint32_t, 4> out;
#if defined(__SSE2__)
        const __m128 f = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(centroid), _mm_load_ps(lo)), _mm_load_ps(scale));
        // Clamped as floats first (maxps(f, 0) is 0 for NaN), so that a centroid far out
        // or NaN never reaches an undefined float-to-int conversion.
        const __m128 clamped = _mm_min_ps(_mm_max_ps(f, _mm_setzero_ps()), _mm_set1_ps(float(bins - 1)));
        _mm_store_si128(reinterpret_cast<__m128i*>(out.data()), _mm_cvttps_epi32(clamped));
#else
        for (int a = 0; a < 4; ++a) {
            const float f = (centroid[a] - lo[a]) * scale[a];
            out[a] = !(f > 0.0f) ? 0 : f >= float(bins - 1) ? bins - 1 : static_cast<uint32_t>(f);
        }
#endif
        return out;
    }
};

}  // namespace glint::sah
