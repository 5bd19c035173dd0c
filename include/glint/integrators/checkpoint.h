#pragma once
/// \file Checkpoints: the film accumulators of a render's finished tiles, so that an
/// interrupted render continues where it stopped (`glint render --resume`) and ends in the
/// image an uninterrupted render gives, bit for bit (every sample is a function of seed,
/// pixel and sample index, and a tile is saved only when all its samples are in).

#include "glint/image/aov_film.h"
#include "glint/image/film.h"
#include "glint/integrators/render_settings.h"
#include "glint/integrators/tile_grid.h"
#include "glint/scene/camera.h"
#include "glint/util/named_values.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace glint {

class CheckpointError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// What a render is made of, as (name, value) pairs in words: the scene file's name and a
/// hash of its bytes, and every setting that changes the image. A checkpoint is resumed
/// only by a render with the same fingerprint.
using RenderFingerprint = NamedValues;

/// The scene file's part of a fingerprint: its name and a hash of its bytes; `scene_file`
/// empty stands for the built-in scene. A large file (a mesh given as the scene) takes tens
/// of milliseconds to read and hash, so the render command does it on a thread of its own
/// while the scene loads. Throws CheckpointError if the file cannot be read.
[[nodiscard]] RenderFingerprint scene_file_fingerprint(const std::filesystem::path& scene_file);

/// `scene` from scene_file_fingerprint, followed by the settings. `camera` is the one
/// rendered through: command-line options (--aperture, --focus, --shutter, --time,
/// --camera) change it without changing the file.
[[nodiscard]] RenderFingerprint render_fingerprint(RenderFingerprint scene, const RenderSettings& s,
                                                   const Camera& camera);

/// Where the checkpoint of the image `output` lives: beside it, `<output>.checkpoint`.
[[nodiscard]] std::filesystem::path checkpoint_path_for(const std::filesystem::path& output);

/// The temporary name write_checkpoint writes `path` under before renaming it into place.
[[nodiscard]] std::filesystem::path temporary_checkpoint_path(const std::filesystem::path& path);

/// Save the finished tiles of `film` with `fingerprint`, under a temporary name renamed into
/// place (a checkpoint is whole or absent). Safe while other threads render unfinished
/// tiles: only finished tiles' pixels are read. With `aovs` (a render with AOVs), their
/// accumulators too. Throws CheckpointError.
void write_checkpoint(const std::filesystem::path& path, const RenderFingerprint& fingerprint, const Film& film,
                      const TileGrid& tiles, const AovFilm* aovs = nullptr);

/// Restore a checkpoint into an empty `film` and `tiles` of the render whose fingerprint is
/// `expected`. Throws CheckpointError naming the file and, for another render's
/// checkpoint, every setting that differs ("spp: the checkpoint has 16, this render 4").
void read_checkpoint(const std::filesystem::path& path, const RenderFingerprint& expected, Film& film, TileGrid& tiles,
                     AovFilm* aovs = nullptr);

}  // namespace glint
