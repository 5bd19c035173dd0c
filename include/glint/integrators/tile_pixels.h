#pragma once
/// \file A finished tile's accumulators as bytes: what a checkpoint saves of each tile and
/// what a rank of a distributed render (mpirun) sends rank 0. The film's per-pixel sums
/// (and the AOVs'), not finished values, so that nothing is rounded on the way.

#include "glint/image/aov_film.h"
#include "glint/image/film.h"
#include "glint/integrators/tile_grid.h"
#include "glint/util/byte_stream.h"

namespace glint {

/// Append the pixels of `tile` in `film` (then in `aovs`, when given), row by row.
void write_tile_pixels(ByteWriter& out, const Film& film, const AovFilm* aovs, const TileGrid::Bounds& tile);

/// Read what write_tile_pixels wrote into the same tile of `film` (and `aovs`). Throws
/// ByteStreamError when the bytes run out.
void read_tile_pixels(ByteReader& in, Film& film, AovFilm* aovs, const TileGrid::Bounds& tile);

}  // namespace glint
