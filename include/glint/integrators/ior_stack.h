#pragma once
/// \file The stack of indices of refraction a ray is inside (handout §5.4.1).

#include <array>
#include <cstdint>
#include <optional>

namespace glint {

/// Tracks nested dielectrics. Entering a dielectric pushes its material; leaving removes
/// the innermost entry of that material. If a boundary was missed (leaving a material the
/// stack does not hold, or a stack that overflowed) the stack stays valid: leaving an
/// unknown material keeps the current medium, and overflow drops the outermost entry.
class IorStack {
public:
    static constexpr int kCapacity = 8;

    explicit IorStack(float ambient_ior = 1.0f) : ambient_(ambient_ior) {}

    /// Index of refraction of the medium the ray is currently in.
    [[nodiscard]] float current() const { return size_ == 0 ? ambient_ : entries_[size_ - 1].ior; }
    /// The material whose medium the ray is in (the innermost entry); nullopt outside all.
    [[nodiscard]] std::optional<uint32_t> current_medium() const {
        return size_ == 0 ? std::nullopt : std::optional<uint32_t>(entries_[size_ - 1].material);
    }
    /// Index on the far side when leaving `material` (the medium that encloses it).
    [[nodiscard]] float outside_of(uint32_t material) const;
    /// Stack after entering `material` with index `ior`.
    [[nodiscard]] IorStack entered(uint32_t material, float ior) const;
    /// Stack after leaving `material`.
    [[nodiscard]] IorStack left(uint32_t material) const;
    [[nodiscard]] int depth() const { return size_; }
    /// True if the ray is inside `material` by the stack's account.
    [[nodiscard]] bool contains(uint32_t material) const { return find(material) >= 0; }
    /// True once an overflow dropped an entry: the stack may no longer know every medium.
    [[nodiscard]] bool lost_entries() const { return lost_entries_; }

private:
    struct Entry {
        uint32_t material;
        float ior;
    };
    /// Position of the innermost entry of `material`, or -1.
    [[nodiscard]] int find(uint32_t material) const;

    std::array<Entry, kCapacity> entries_{};
    int size_ = 0;
    bool lost_entries_ = false;
    float ambient_;
};

}  // namespace glint
