#pragma once
/// \file Flat binary records in native byte order, for data that stays on the machine that
/// wrote it: checkpoints, and the meshes an import child process hands back. The reader
/// checks every length against what is left before it allocates or copies, so a cut-short
/// or damaged record becomes a ByteStreamError, never an out-of-bounds read or a huge
/// allocation.

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace glint {

/// The data ended before a record did, or a length in it cannot be right.
struct ByteStreamError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class ByteWriter {
public:
    /// A trivially copyable value, as its bytes.
    template <class T>
    void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        raw(&v, sizeof v);
    }
    void u32(uint32_t v) { value(v); }
    /// A 32-bit length, then the characters.
    void text(std::string_view s) {
        value(uint32_t(s.size()));
        raw(s.data(), s.size());
    }
    /// A 64-bit count, then the elements' bytes.
    template <class T, class Allocator>
    void array(const std::vector<T, Allocator>& items) {
        static_assert(std::is_trivially_copyable_v<T>);
        value(uint64_t(items.size()));
        raw(items.data(), items.size() * sizeof(T));
    }
    void raw(const void* data, std::size_t size) {
        const auto* p = static_cast<const char*>(data);
        bytes_.append(p, size);
    }
    /// Room for `size` bytes in all, so that a large record is not copied as it grows.
    void reserve(std::size_t size) { bytes_.reserve(size); }
    [[nodiscard]] const std::string& bytes() const { return bytes_; }
    [[nodiscard]] std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
};

class ByteReader {
public:
    explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}

    template <class T>
    [[nodiscard]] T value() {
        static_assert(std::is_trivially_copyable_v<T>);
        T v;
        raw(&v, sizeof v);
        return v;
    }
    [[nodiscard]] uint32_t u32() { return value<uint32_t>(); }
    [[nodiscard]] std::string text() {
        const std::size_t n = count<uint32_t>(1);
        std::string s(bytes_.substr(at_, n));
        at_ += n;
        return s;
    }
    /// What ByteWriter::array wrote, into `items` (replacing what it held), so that it lands
    /// in the destination's own storage, whatever its allocator.
    template <class T, class Allocator>
    void array(std::vector<T, Allocator>& items) {
        static_assert(std::is_trivially_copyable_v<T>);
        items.resize(count<uint64_t>(sizeof(T)));
        raw(items.data(), items.size() * sizeof(T));
    }
    void raw(void* out, std::size_t size) {
        need(size);
        if (size > 0) std::memcpy(out, bytes_.data() + at_, size);
        at_ += size;
    }
    [[nodiscard]] bool at_end() const { return at_ == bytes_.size(); }

private:
    /// A stored count of items of `item_size` bytes each, checked against what is left.
    template <class Count>
    std::size_t count(std::size_t item_size) {
        const uint64_t n = value<Count>();
        if (n > (bytes_.size() - at_) / item_size) throw ByteStreamError("a length runs past the end of the data");
        return std::size_t(n);
    }
    void need(std::size_t n) const {
        if (bytes_.size() - at_ < n) throw ByteStreamError("the data ends early");
    }
    std::string_view bytes_;
    std::size_t at_ = 0;
};

}  // namespace glint
