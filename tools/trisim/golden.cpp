// SPDX-License-Identifier: MIT
#include "golden.h"

#include <signal.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "common/errors.h"
#include "core_bridge/pixel_format_names.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "reference/fit_names.h"
#include "picture.h"

namespace tristream::trisim {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* manifest_name = "golden.json";

// One picture of DIR: its input, its golden, the settings of its render and its tolerances.
struct Picture {
  std::string file;  // the input's name in DIR
  std::string name;  // the input's name without its extension: <name>.png is the golden
  RenderRequest req;
  std::optional<double> max_mse;
  std::optional<long long> max_changed;
};

// Inputs are the regular files of DIR named *.tri or starting with a blob's magic ("TST": TSTB,
// TSTC), in name order.
std::vector<std::string> list_inputs(const std::string& dir) {
  std::error_code ec;
  fs::directory_iterator it(dir, ec);
  if (ec) throw InputError(dir + ": cannot read the directory (" + ec.message() + ")");
  std::vector<std::string> names;
  for (const fs::directory_entry& e : it) {
    if (!e.is_regular_file(ec)) continue;
    const std::string name = e.path().filename().string();
    bool input = name.size() > 4 && name.compare(name.size() - 4, 4, ".tri") == 0;
    if (!input) {
      char magic[3] = {};
      std::ifstream f(e.path(), std::ios::binary);
      input = f.read(magic, 3) && std::string_view(magic, 3) == "TST";
    }
    if (input) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

[[noreturn]] void bad_value(const std::string& where, const std::string& key, const std::string& expected,
                            const json& v) {
  throw DataError(where + ": \"" + key + "\": expected " + expected + ", found " + v.dump());
}

long long int_in(const std::string& where, const std::string& key, const json& v, long long lo, long long hi) {
  if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
    bad_value(where, key, "an integer from " + std::to_string(lo) + " to " + std::to_string(hi), v);
  return v.get<long long>();
}

std::string one_of(const std::string& where, const std::string& key, const json& v,
                   const std::vector<std::string>& choices) {
  std::string list;
  for (const std::string& c : choices) list += (list.empty() ? "" : ", ") + c;
  if (!v.is_string() || std::find(choices.begin(), choices.end(), v.get<std::string>()) == choices.end())
    bad_value(where, key, "one of " + list, v);
  return v.get<std::string>();
}

// One setting of the manifest (an object of "defaults" or "pictures"); its key is the trisim
// render option's name without the dashes.
void apply_setting(const std::string& where, const std::string& key, const json& v, Picture& p) {
  RenderRequest& r = p.req;
  if (key == "engine") r.engine = one_of(where, key, v, {"reference", "core"});
  else if (key == "method") r.method = one_of(where, key, v, method_names());
  else if (key == "variant") {
    if (!v.is_string()) bad_value(where, key, "a string", v);
    r.variant = v.get<std::string>();
  }
  else if (key == "width") r.width = int(int_in(where, key, v, 1, 65535));
  else if (key == "height") r.height = int(int_in(where, key, v, 1, 65535));
  else if (key == "fit") r.fit = one_of(where, key, v, fit_name_list());
  else if (key == "format") r.format = one_of(where, key, v, pixel_format_name_list());
  else if (key == "dither") {
    if (!v.is_boolean()) bad_value(where, key, "true or false", v);
    r.dither = v.get<bool>();
  }
  else if (key == "tile") r.tile = int(int_in(where, key, v, 0, 2048));
  else if (key == "tile-width") r.tile_width = int(int_in(where, key, v, 0, 2048));
  else if (key == "tile-height") r.tile_height = int(int_in(where, key, v, 0, 2048));
  else if (key == "background") {
    if (v.is_number_integer()) r.background = Background(std::uint8_t(int_in(where, key, v, 0, 255)));
    else if (v.is_array() && v.size() == 3)
      r.background = Background(std::uint8_t(int_in(where, key, v[0], 0, 255)),
                                std::uint8_t(int_in(where, key, v[1], 0, 255)),
                                std::uint8_t(int_in(where, key, v[2], 0, 255)));
    else bad_value(where, key, "a value 0 to 255 or [R, G, B]", v);
  } else if (key == "viewport") {
    if (!v.is_array() || v.size() != 4) bad_value(where, key, "[X0, Y0, X1, Y1]", v);
    long long c[4];
    for (int i = 0; i < 4; ++i) c[i] = int_in(where, key, v[i], 0, 65535);
    if (c[2] <= c[0] || c[3] <= c[1]) bad_value(where, key, "[X0, Y0, X1, Y1] with X0 < X1 and Y0 < Y1", v);
    r.viewport = core::Rect{std::int32_t(c[0]), std::int32_t(c[1]), std::int32_t(c[2]), std::int32_t(c[3])};
  } else if (key == "max-mse") {
    if (!v.is_number() || v.get<double>() < 0) bad_value(where, key, "a number >= 0", v);
    p.max_mse = v.get<double>();
    return;
  } else if (key == "max-changed-pixels") {
    p.max_changed = int_in(where, key, v, 0, 1LL << 40);
    return;
  } else {
    throw DataError(where + ": unknown setting \"" + key +
                    "\" (expected engine, method, variant, width, height, fit, format, dither, tile, tile-width, "
                    "tile-height, viewport, background, max-mse or max-changed-pixels)");
  }
  r.given.insert("--" + key);
}

void apply_settings(const std::string& where, const json& settings, Picture& p) {
  if (!settings.is_object()) bad_value(where, "settings", "an object", settings);
  for (const auto& [key, value] : settings.items()) apply_setting(where, key, value, p);
}

// The manifest: {"defaults": {settings}, "pictures": {"<file>": {settings}}}, both optional.
json read_manifest(const std::string& path) {
  json j;
  try {
    j = json::parse(read_file(path));
  } catch (const json::parse_error& e) {
    const std::string what = e.what();
    throw DataError(path + ": byte " + std::to_string(e.byte) + ": expected JSON (" + what.substr(what.find(']') + 2) +
                    ")");
  }
  if (!j.is_object()) throw DataError(path + ": expected a JSON object, found " + std::string(j.type_name()));
  for (const auto& [key, value] : j.items())
    if (key != "defaults" && key != "pictures")
      throw DataError(path + ": unknown key \"" + key + "\" (expected \"defaults\" and \"pictures\")");
  if (j.contains("pictures") && !j["pictures"].is_object())
    throw DataError(path + ": \"pictures\": expected an object of file names, found " + j["pictures"].dump());
  return j;
}

// The pictures of DIR with their settings: the manifest's defaults, then the picture's own.
std::vector<Picture> load_pictures(const std::string& dir) {
  const std::string manifest_path = (fs::path(dir) / manifest_name).string();
  json manifest = json::object();
  if (fs::exists(manifest_path)) manifest = read_manifest(manifest_path);
  const std::vector<std::string> files = list_inputs(dir);
  if (manifest.contains("pictures"))
    for (const auto& [file, settings] : manifest["pictures"].items())
      if (std::find(files.begin(), files.end(), file) == files.end())
        throw DataError(manifest_path + ": \"pictures\": \"" + file + "\": expected a .tri or blob file in " + dir +
                        ", found none");
  std::vector<Picture> pictures;
  std::map<std::string, std::string> by_name;
  for (const std::string& file : files) {
    Picture p;
    p.file = file;
    p.name = fs::path(file).stem().string();
    if (const auto [it, fresh] = by_name.emplace(p.name, file); !fresh)
      throw DataError(dir + ": " + it->second + " and " + file + " would share the golden " + p.name +
                      ".png: rename one");
    p.req.input = (fs::path(dir) / file).string();
    if (manifest.contains("defaults")) apply_settings(manifest_path + ": \"defaults\"", manifest["defaults"], p);
    if (manifest.contains("pictures") && manifest["pictures"].contains(file))
      apply_settings(manifest_path + ": \"pictures\": \"" + file + "\"", manifest["pictures"][file], p);
    pictures.push_back(std::move(p));
  }
  return pictures;
}

// The picture as trisim render writes it. Settings that the render cannot take are errors in
// the manifest (65), named with the picture.
Image render_golden(Picture& p, const std::string& dir) {
  try {
    const Input in = read_input(p.req.input, needs_mesh(p.req));
    resolve_blob_request(in, p.req, p.req.was_given("--method"));
    check_engine_options(p.req);
    check_render_size(in.tri, p.req);
    return render_picture(in, p.req);
  } catch (const UsageError& e) {
    throw DataError((fs::path(dir) / manifest_name).string() + ": " + p.file + ": " + e.what());
  }
}

// How a render differs from its golden.
struct Difference {
  bool golden_found = false;
  std::string shape;  // not empty when the sizes or channel counts differ: what they are
  long long changed = 0;  // pixels with any channel changed
  int largest = 0;        // largest difference of a channel value
  double mse = 0;         // over every channel value, as trisim metrics
  bool identical() const { return golden_found && shape.empty() && changed == 0; }
};

Difference compare(const Image& render, const std::string& golden_path) {
  Difference d;
  if (!fs::exists(golden_path)) return d;
  const Image golden = read_image(golden_path);
  d.golden_found = true;
  auto shape = [](const Image& i) {
    return std::to_string(i.width) + "x" + std::to_string(i.height) + (i.channels == 1 ? " grey" : " RGB");
  };
  if (golden.width != render.width || golden.height != render.height || golden.channels != render.channels) {
    d.shape = "the render is " + shape(render) + ", the golden " + shape(golden);
    return d;
  }
  const int nc = render.channels;
  double sum = 0;
  for (std::size_t i = 0; i < std::size_t(render.width) * render.height; ++i) {
    bool changed = false;
    for (int c = 0; c < nc; ++c) {
      const int diff = std::abs(int(render.pixels[i * nc + c]) - int(golden.pixels[i * nc + c]));
      changed = changed || diff != 0;
      d.largest = std::max(d.largest, diff);
      sum += double(diff) * diff;
    }
    d.changed += changed;
  }
  d.mse = render.pixels.empty() ? 0 : sum / double(render.pixels.size());
  return d;
}

// The changed pixels in red over the render dimmed to grey (64 + luma / 4, so that red stands out).
Image diff_image(const Image& render, const std::string& golden_path) {
  const Image golden = read_image(golden_path);
  const Image grey = to_grey(render);
  Image out(render.width, render.height, 3);
  const int nc = render.channels;
  for (std::size_t i = 0; i < std::size_t(render.width) * render.height; ++i) {
    bool changed = false;
    for (int c = 0; c < nc; ++c) changed = changed || render.pixels[i * nc + c] != golden.pixels[i * nc + c];
    const std::uint8_t dim = std::uint8_t(64 + grey.pixels[i] / 4);
    out.pixels[3 * i] = changed ? 255 : dim;
    out.pixels[3 * i + 1] = changed ? 0 : dim;
    out.pixels[3 * i + 2] = changed ? 0 : dim;
  }
  return out;
}

// The signals that end a tool and that an update holds back: SIGINT, SIGTERM, SIGHUP, SIGQUIT.
constexpr int held_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

// Those signals held back while alive: the destructor restores the mask, and a signal that came
// meanwhile is delivered then.
class HeldSignals {
 public:
  HeldSignals() {
    sigset_t block;
    sigemptyset(&block);
    for (int sig : held_signals) sigaddset(&block, sig);
    ::sigprocmask(SIG_BLOCK, &block, &old_);
  }
  ~HeldSignals() { ::sigprocmask(SIG_SETMASK, &old_, nullptr); }
  HeldSignals(const HeldSignals&) = delete;
  HeldSignals& operator=(const HeldSignals&) = delete;
  bool pending() const {
    sigset_t p;
    sigpending(&p);
    for (int sig : held_signals)
      if (sigismember(&p, sig) == 1) return true;
    return false;
  }

 private:
  sigset_t old_;
};

// Writes every file (path, bytes) or none: each to a temporary file in its directory, synced,
// and only when all are written are they renamed over the goldens. A failure or a signal of
// held_signals before the renames removes the temporary files and leaves every golden as it was;
// the signals are held back during the renames, which then all happen.
void write_all_or_none(const std::vector<std::pair<std::string, std::string>>& files) {
  HeldSignals held;  // declared first, destroyed last: after the temporary files are gone or renamed
  std::vector<std::unique_ptr<AtomicFile>> written;
  for (const auto& [path, bytes] : files) {
    if (held.pending()) return;
    written.push_back(std::make_unique<AtomicFile>(path));
    written.back()->write(bytes);
    written.back()->sync();
  }
  if (held.pending()) return;
  for (auto& f : written) f->commit();
}

void print_difference(const Picture& p, const Difference& d, bool passes, const std::string& diff_path) {
  if (!d.golden_found) {
    std::printf("%s: no golden %s.png (trisim golden --update writes it)\n", p.name.c_str(), p.name.c_str());
  } else if (!d.shape.empty()) {
    std::printf("%s: %s\n", p.name.c_str(), d.shape.c_str());
  } else {
    std::printf("%s: %lld pixels changed, largest difference %d, MSE %.6f%s%s\n", p.name.c_str(), d.changed,
                d.largest, d.mse, passes ? " (within its tolerance)" : "",
                diff_path.empty() ? "" : (", diff " + diff_path).c_str());
  }
}

// Whether a picture that differs passes: its tolerances (zero by default) hold.
bool within_tolerance(const Picture& p, const Difference& d) {
  if (!d.golden_found || !d.shape.empty()) return false;
  if (!p.max_mse && !p.max_changed) return d.changed == 0;
  return (!p.max_mse || d.mse <= *p.max_mse) && (!p.max_changed || d.changed <= *p.max_changed);
}

}  // namespace

CLI::App* add_golden_command(CLI::App& app, GoldenCommand& c) {
  auto* cmd = app.add_subcommand(
      "golden",
      "Render every .tri and blob of DIR with the settings of DIR/golden.json and compare each with its golden PNG "
      "(<name>.png): exit 0 when all are identical, 1 when any differs (docs/GOLDEN.md)");
  cmd->add_option("dir", c.dir, "Directory of the pictures, their goldens and golden.json")->required();
  cmd->add_flag("--update", c.update,
                "Write the goldens that differ or are missing (all or none: through temporary files renamed at the end)");
  cmd->add_option("--diff-dir", c.diff_dir,
                  "Where <name>.diff.png goes for a picture that differs: its changed pixels in red over the render "
                  "dimmed (created when needed)")
      ->capture_default_str();
  return cmd;
}

int run_golden(const GoldenCommand& c) {
  std::vector<Picture> pictures = load_pictures(c.dir);
  if (pictures.empty()) throw InputError(c.dir + ": expected .tri or blob files, found none");
  std::vector<std::pair<std::string, std::string>> updates;
  int failed = 0, tolerated = 0, missing = 0;
  for (Picture& p : pictures) {
    const Image image = render_golden(p, c.dir);
    const std::string golden_path = (fs::path(c.dir) / (p.name + ".png")).string();
    Difference d;
    try {
      d = compare(image, golden_path);
    } catch (const DataError&) {
      if (!c.update) throw;  // a golden that is not a PNG: --update replaces it
    }
    if (d.identical()) continue;
    if (c.update) {
      updates.emplace_back(golden_path, encode_png(image, golden_path));
      continue;
    }
    const bool passes = within_tolerance(p, d);
    std::string diff_path;
    if (!passes && d.golden_found && d.shape.empty()) {
      make_directories(c.diff_dir, "--diff-dir");
      diff_path = (fs::path(c.diff_dir) / (p.name + ".diff.png")).string();
      write_png(diff_path, diff_image(image, golden_path));
    }
    print_difference(p, d, passes, diff_path);
    (passes ? tolerated : d.golden_found ? failed : missing) += 1;
  }
  if (c.update) {
    write_all_or_none(updates);
    for (const auto& [path, bytes] : updates) std::printf("updated %s\n", path.c_str());
    std::printf("golden: %zu pictures, %zu goldens written\n", pictures.size(), updates.size());
    return exit_ok;
  }
  std::printf("golden: %zu pictures, %zu identical, %d within tolerance, %d differ, %d without a golden\n",
              pictures.size(), pictures.size() - std::size_t(failed + tolerated + missing), tolerated, failed, missing);
  return failed || missing ? exit_check_failed : exit_ok;
}

}  // namespace tristream::trisim
