#include "glint/integrators/ior_stack.h"

namespace glint {

int IorStack::find(uint32_t material) const {
    for (int i = size_ - 1; i >= 0; --i)
        if (entries_[i].material == material) return i;
    return -1;
}

float IorStack::outside_of(uint32_t material) const {
    const int i = find(material);
    if (i < 0) return current();  // missed the entry boundary: assume the medium we think we are in
    // The medium enclosing `material` is the innermost one entered before it.
    return i == 0 ? ambient_ : entries_[i - 1].ior;
}

IorStack IorStack::entered(uint32_t material, float ior) const {
    IorStack next = *this;
    if (next.size_ == kCapacity) {
        for (int i = 1; i < kCapacity; ++i) next.entries_[i - 1] = next.entries_[i];
        --next.size_;
        next.lost_entries_ = true;
    }
    next.entries_[next.size_++] = {material, ior};
    return next;
}

IorStack IorStack::left(uint32_t material) const {
    IorStack next = *this;
    const int i = find(material);
    if (i < 0) return next;
    for (int k = i + 1; k < next.size_; ++k) next.entries_[k - 1] = next.entries_[k];
    --next.size_;
    return next;
}

}  // namespace glint
