#include "glint/integrators/checkpoint.h"

#include "glint/integrators/tile_pixels.h"

#include "glint/image/filter.h"
#include "glint/util/byte_stream.h"
#include "glint/util/move_into_place.h"
#include "glint/util/whole_file.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstring>
#include <fstream>
#include <optional>
#include <string_view>
#include <utility>

#include <unistd.h>

namespace glint {

namespace {

// Layout (native byte order: a checkpoint resumes on the machine kind that wrote it):
//   "GLINTCKP", u32 version, u32 item count, items as (u32 length, bytes) name/value pairs,
//   u32 width, u32 height, u32 tile count, one byte per tile (1 = finished), then the
//   FilmPixel records of every finished tile in tile order, row by row within the tile, each
//   tile's followed by its AovPixel records when the render has AOVs (its fingerprint says).
constexpr char kMagic[8] = {'G', 'L', 'I', 'N', 'T', 'C', 'K', 'P'};
constexpr uint32_t kVersion = 1;

/// FNV-1a, 64 bits: enough to tell an edited scene file from the one a checkpoint saw.
uint64_t fnv1a(const std::string& bytes) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (const unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
    return h;
}

std::string file_bytes(const std::filesystem::path& path) {
    std::optional<std::string> bytes = read_whole_file(path);
    if (!bytes) throw CheckpointError(path.string() + ": cannot be read");
    return std::move(*bytes);
}

}  // namespace

RenderFingerprint scene_file_fingerprint(const std::filesystem::path& scene_file) {
    if (scene_file.empty()) return {{"scene", "the built-in scene"}};
    return {{"scene", scene_file.filename().string()},
            {"scene content", fmt::format("{:016x}", fnv1a(file_bytes(scene_file)))}};
}

RenderFingerprint render_fingerprint(RenderFingerprint scene, const RenderSettings& s, const Camera& camera) {
    RenderFingerprint f = std::move(scene);
    // Nine significant digits: a float's value exactly, so any change of the camera shows.
    const Vec3 &e = camera.eye(), &d = camera.forward(), &u = camera.up();
    f.emplace_back(
        "camera",
        fmt::format("{} at ({:.9g}, {:.9g}, {:.9g}) looking ({:.9g}, {:.9g}, {:.9g}) up ({:.9g}, "
                    "{:.9g}, {:.9g}), {} {:.9g}",
                    camera.projection() == Projection::Perspective ? "perspective" : "orthographic", e.x, e.y, e.z, d.x,
                    d.y, d.z, u.x, u.y, u.z, camera.projection() == Projection::Perspective ? "fov" : "height",
                    camera.projection() == Projection::Perspective ? camera.vertical_fov() : camera.view_height()));
    const ThinLens& lens = camera.lens();
    f.emplace_back("lens", fmt::format("aperture {:.9g}, focus {:.9g}, blades {}, rotation {:.9g}",
                                       lens.aperture_radius, lens.focus_distance, lens.blades, lens.rotation));
    f.emplace_back("shutter", fmt::format("[{:.9g}, {:.9g}]", camera.shutter().open, camera.shutter().close));
    if (camera.moves()) {
        std::string keys;
        for (const Camera::Key& k : camera.motion())
            keys += fmt::format("{}at {:.9g}: ({:.9g}, {:.9g}, {:.9g}) looking at ({:.9g}, {:.9g}, {:.9g})",
                                keys.empty() ? "" : "; ", k.time, k.eye.x, k.eye.y, k.eye.z, k.target.x, k.target.y,
                                k.target.z);
        f.emplace_back("camera motion", keys);
    }
    f.emplace_back("width", std::to_string(s.width));
    f.emplace_back("height", std::to_string(s.height));
    f.emplace_back("spp", std::to_string(s.samples_per_axis * s.samples_per_axis));
    f.emplace_back("max_depth", std::to_string(s.max_depth));
    f.emplace_back("seed", std::to_string(s.seed));
    f.emplace_back("integrator", s.integrator);
    f.emplace_back("filter", std::string(filter_name(s.filter)));
    f.emplace_back("filter_radius", fmt::format("{}", s.filter_radius));
    f.emplace_back("light_samples", std::to_string(s.light_samples));
    f.emplace_back("glossy_samples", std::to_string(s.glossy_samples));
    f.emplace_back("mis", s.mis == MisHeuristic::Balance ? "balance" : "power");
    if (s.adaptive)
        f.emplace_back("adaptive", fmt::format("min_spp {}, threshold {}", s.adaptive->min_spp, s.adaptive->threshold));
    if (!s.aovs.empty()) {
        std::vector<std::string_view> names;
        for (const Aov aov : s.aovs) names.push_back(aov_name(aov));
        f.emplace_back("aovs", fmt::format("{}", fmt::join(names, ",")));
    }
    return f;
}

std::filesystem::path checkpoint_path_for(const std::filesystem::path& output) {
    std::filesystem::path p = output;
    p += ".checkpoint";
    return p;
}

std::filesystem::path temporary_checkpoint_path(const std::filesystem::path& path) {
    std::filesystem::path tmp = path;
    tmp += ".partial-" + std::to_string(::getpid());
    return tmp;
}

void write_checkpoint(const std::filesystem::path& path, const RenderFingerprint& fingerprint, const Film& film,
                      const TileGrid& tiles, const AovFilm* aovs) {
    ByteWriter w;
    w.raw(kMagic, sizeof kMagic);
    w.u32(kVersion);
    write_named_values(w, fingerprint);
    w.u32(film.width());
    w.u32(film.height());
    w.u32(tiles.count());
    // Read each flag once: a tile finishing meanwhile is saved next time, never half.
    std::string done(tiles.count(), '\0');
    for (uint32_t t = 0; t < tiles.count(); ++t) done[t] = tiles.done(t) ? 1 : 0;
    w.raw(done.data(), done.size());
    for (uint32_t t = 0; t < tiles.count(); ++t)
        if (done[t]) write_tile_pixels(w, film, aovs, tiles.bounds(t));
    const std::filesystem::path tmp = temporary_checkpoint_path(path);
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out.write(w.bytes().data(), std::streamsize(w.bytes().size()));
        if (!out.flush()) {
            std::error_code ec;
            std::filesystem::remove(tmp, ec);
            throw CheckpointError(path.string() + ": cannot write the checkpoint");
        }
    }
    if (const std::string reason = move_into_place(tmp, path); !reason.empty())
        throw CheckpointError(path.string() + ": cannot move the checkpoint into place: " + reason);
}

namespace {

/// A record that cannot be a checkpoint's; read_checkpoint() words it.
[[noreturn]] void malformed() { throw ByteStreamError("malformed"); }

/// The fingerprint saved in a checkpoint, after its magic and version.
RenderFingerprint read_fingerprint(ByteReader& r) {
    char magic[sizeof kMagic];
    r.raw(magic, sizeof magic);
    if (std::memcmp(magic, kMagic, sizeof kMagic) != 0 || r.u32() != kVersion) malformed();
    return read_named_values(r, 1024);
}

/// "name: the checkpoint has A, this render B; ..." for each item that differs.
std::string fingerprint_differences(const RenderFingerprint& saved, const RenderFingerprint& expected) {
    std::string differences;
    for (const auto& [name, theirs, ours] : named_value_differences(saved, expected))
        differences += fmt::format("{}{}: the checkpoint has {}, this render {}", differences.empty() ? "" : "; ", name,
                                   theirs, ours);
    return differences.empty() ? std::string("its description differs") : differences;
}

}  // namespace

void read_checkpoint(const std::filesystem::path& path, const RenderFingerprint& expected, Film& film, TileGrid& tiles,
                     AovFilm* aovs) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw CheckpointError(path.string() +
                              ": no checkpoint to resume (an interrupted render leaves one beside "
                              "its image)");
    const std::string bytes = file_bytes(path);
    try {
        ByteReader r(bytes);
        const RenderFingerprint saved = read_fingerprint(r);
        if (saved != expected)
            throw CheckpointError(path.string() + ": made by another render (" +
                                  fingerprint_differences(saved, expected) +
                                  "); delete it or render with the settings it was made with");
        if (r.u32() != film.width() || r.u32() != film.height() || r.u32() != tiles.count()) malformed();
        std::string done(tiles.count(), '\0');
        r.raw(done.data(), done.size());
        for (uint32_t t = 0; t < tiles.count(); ++t) {
            if (done[t] == 0) continue;
            if (done[t] != 1) malformed();
            read_tile_pixels(r, film, aovs, tiles.bounds(t));
            tiles.mark_done(t);
        }
        if (!r.at_end()) malformed();
    } catch (const ByteStreamError&) {
        throw CheckpointError(path.string() + ": not a Glint checkpoint, or cut short (delete it to start over)");
    }
}

}  // namespace glint
