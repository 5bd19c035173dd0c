#include "glint/util/named_values.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

TEST(NamedValues, DifferencesNameEveryItemThatDiffersOnEitherSide) {
    const NamedValues first{{"spp", "16"}, {"seed", "1"}, {"integrator", "path"}};
    const NamedValues second{{"seed", "1"}, {"spp", "4"}, {"crop", "0 0 8 8"}};
    const auto differences = named_value_differences(first, second);
    ASSERT_EQ(differences.size(), 3u);
    EXPECT_EQ(differences[0].name, "spp");
    EXPECT_EQ(differences[0].first, "16");
    EXPECT_EQ(differences[0].second, "4");
    EXPECT_EQ(differences[1].name, "integrator");
    EXPECT_EQ(differences[1].second, "nothing");
    EXPECT_EQ(differences[2].name, "crop");
    EXPECT_EQ(differences[2].first, "nothing");
    EXPECT_TRUE(named_value_differences(first, first).empty());
}

TEST(NamedValues, ReadBackAsWrittenAndRefusedPastTheirBound) {
    const NamedValues values{{"scene", "a.toml"}, {"spp", "16"}};
    ByteWriter w;
    write_named_values(w, values);
    ByteReader r(w.bytes());
    EXPECT_EQ(read_named_values(r, 2), values);
    EXPECT_TRUE(r.at_end());
    ByteReader bounded(w.bytes());
    EXPECT_THROW((void)read_named_values(bounded, 1), ByteStreamError);
    const std::string cut = w.bytes().substr(0, w.bytes().size() - 1);
    ByteReader short_read(cut);
    EXPECT_THROW((void)read_named_values(short_read, 2), ByteStreamError);
}

}  // namespace
}  // namespace glint
