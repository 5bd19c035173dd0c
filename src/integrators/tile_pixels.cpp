#include "glint/integrators/tile_pixels.h"

namespace glint {

void write_tile_pixels(ByteWriter& out, const Film& film, const AovFilm* aovs, const TileGrid::Bounds& tile) {
    const auto [x0, y0, x1, y1] = tile;
    for (uint32_t y = y0; y < y1; ++y)
        out.raw(&film.pixels()[std::size_t(y) * film.width() + x0], (x1 - x0) * sizeof(FilmPixel));
    if (aovs)
        for (uint32_t y = y0; y < y1; ++y)
            out.raw(&aovs->pixels()[std::size_t(y) * film.width() + x0], (x1 - x0) * sizeof(AovPixel));
}

void read_tile_pixels(ByteReader& in, Film& film, AovFilm* aovs, const TileGrid::Bounds& tile) {
    const auto [x0, y0, x1, y1] = tile;
    for (uint32_t y = y0; y < y1; ++y)
        in.raw(&film.pixels()[std::size_t(y) * film.width() + x0], (x1 - x0) * sizeof(FilmPixel));
    if (aovs)
        for (uint32_t y = y0; y < y1; ++y)
            in.raw(&aovs->pixels()[std::size_t(y) * film.width() + x0], (x1 - x0) * sizeof(AovPixel));
}

}  // namespace glint
