#include "glint/util/huge_page_array.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

namespace glint {
namespace {

/// The kernel's transparent-huge-page mode ("always", "madvise" or "never"), or "" where it
/// has none (not Linux, or a kernel without them).
std::string huge_page_mode() {
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string line;
    if (!std::getline(in, line)) return "";
    const auto open = line.find('['), close = line.find(']');
    return open == std::string::npos || close == std::string::npos ? "" : line.substr(open + 1, close - open - 1);
}

/// What /proc/self/smaps says of the mapping holding `address`: its "THPeligible" flag
/// (whether the kernel may back it with huge pages), -1 when not found.
int huge_page_eligible(const void* address) {
    std::ifstream smaps("/proc/self/smaps");
    const auto at = reinterpret_cast<std::uintptr_t>(address);
    bool inside = false;
    for (std::string line; std::getline(smaps, line);) {
        std::uintptr_t begin = 0, end = 0;
        char dash = 0;
        std::istringstream range(line);
        if (range >> std::hex >> begin >> dash >> end && dash == '-') {
            inside = begin <= at && at < end;
            continue;
        }
        if (inside && line.starts_with("THPeligible:")) return std::stoi(line.substr(12));
    }
    return -1;
}

TEST(HugePageArray, KeepsItsValuesThroughGrowthAcrossTheHugePageSize) {
    HugePageArray<uint32_t> values;
    const std::size_t count = 3 * kHugePageBytes / sizeof(uint32_t);
    for (std::size_t i = 0; i < count; ++i) values.push_back(uint32_t(i * 2654435761u));
    for (std::size_t i = 0; i < count; i += 4099) ASSERT_EQ(values[i], uint32_t(i * 2654435761u));
    values.resize(10);
    values.shrink_to_fit();
    EXPECT_EQ(values[9], uint32_t(9 * 2654435761u));
}

TEST(HugePageArray, SmallArraysAreAlignedForTheirType) {
    struct alignas(64) Wide {
        float lanes[16];
    };
    const HugePageArray<Wide> small(3);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(small.data()) % 64, 0u);
}

TEST(HugePageArray, ArraysOfHugePagesStartOnOneAndMayUseThem) {
    const HugePageArray<float> large(kHugePageBytes / sizeof(float) + 1);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(large.data()) % kHugePageBytes, 0u);
    const std::string mode = huge_page_mode();
    if (mode != "madvise" && mode != "always")
        GTEST_SKIP() << "transparent huge pages are '" << mode << "' here: nothing to advise";
    // Under "madvise" only the advice makes a mapping eligible.
    EXPECT_EQ(huge_page_eligible(large.data()), 1) << "mode " << mode;
}

}  // namespace
}  // namespace glint
