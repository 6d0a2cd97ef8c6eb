#include "app/cluster/shard_tag.h"

#include "app/cluster/build_id.h"
#include "app/scene/content_hash.h"
#include "io/bad_input.h"
#include "physics/integrator.h"

#include <charconv>
#include <cstdio>
#include <map>
#include <sstream>

namespace tumble::app {

namespace {

constexpr std::string_view kTagName = "tumble-shard/1";

// What the command line can change about the frames beyond the scene file: the motion's
// integrator and step (h as its exact bits) and the picture settings. Written out and hashed,
// so a new switch only needs adding here.
std::string look_hash(const Scene& scene, const Timeline& tl) {
    const RenderSettings& r = scene.render;
    char text[512];
    std::snprintf(text, sizeof text,
                  "integrator=%s h=%a size=%dx%d fps=%d shadows=%d soft_shadows=%d ao=%d "
                  "reflections=%d aa=%d overlay=%d axes=%d vectors=%d",
                  std::string(physics::integrator_info(scene.world.integrator).name).c_str(), tl.h,
                  r.width, r.height, r.fps, r.shadows, r.soft_shadows, r.ambient_occlusion,
                  r.reflections, r.antialiasing, r.overlay, r.axes, r.vectors);
    ContentHash hash;
    hash.add(text);
    return hash.hex();
}

bool to_int(const std::string& s, std::int64_t& out) {
    const auto [at, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && at == s.data() + s.size() && !s.empty();
}

} // namespace

ShardTag shard_tag_for(const Scene& scene, const Timeline& tl, FrameRange range, int crf,
                       const std::string& preset) {
    ShardTag t;
    t.range = range;
    t.frames = tl.frames;
    t.scene = ContentHash::to_hex(scene.content_hash);
    t.look = look_hash(scene, tl);
    t.build = build_id();
    t.width = scene.render.width;
    t.height = scene.render.height;
    t.fps = tl.fps;
    t.codec = "libx264";
    t.crf = crf;
    t.preset = preset;
    t.key_interval = key_interval(tl.fps);
    return t;
}

std::string format_tag(const ShardTag& t) {
    std::ostringstream s;
    s << kTagName << " frames=" << t.range.text() << "/" << t.frames << " scene=" << t.scene
      << " look=" << t.look << " build=" << t.build << " size=" << t.width << "x" << t.height
      << " fps=" << t.fps << " codec=" << t.codec << " crf=" << t.crf << " preset=" << t.preset
      << " keyint=" << t.key_interval;
    return s.str();
}

std::optional<ShardTag> parse_tag(const std::string& comment, const std::string& file) {
    std::istringstream words(comment);
    std::string name;
    words >> name;
    if (!name.starts_with("tumble-shard/")) return std::nullopt;
    const auto bad = [&](const std::string& why) {
        return io::BadInput(file + ": its tumble-shard tag " + why + " (tag: \"" + comment + "\")");
    };
    if (name != kTagName)
        throw bad("is of another version; this tumble reads " + std::string(kTagName));
    std::map<std::string, std::string> kv;
    for (std::string word; words >> word;)
        if (const auto eq = word.find('='); eq != std::string::npos)
            kv[word.substr(0, eq)] = word.substr(eq + 1);
    ShardTag t;
    std::int64_t crf = 0, fps = 0, keyint = 0, w = 0, h = 0;
    const std::string frames = kv["frames"], size = kv["size"];
    const auto colon = frames.find(':'), slash = frames.find('/'), x = size.find('x');
    const bool ok = colon != std::string::npos && slash != std::string::npos && colon < slash &&
                    x != std::string::npos && to_int(frames.substr(0, colon), t.range.first) &&
                    to_int(frames.substr(colon + 1, slash - colon - 1), t.range.end) &&
                    to_int(frames.substr(slash + 1), t.frames) && to_int(size.substr(0, x), w) &&
                    to_int(size.substr(x + 1), h) && to_int(kv["fps"], fps) &&
                    to_int(kv["crf"], crf) && to_int(kv["keyint"], keyint) &&
                    !kv["scene"].empty() && !kv["look"].empty() && !kv["build"].empty() &&
                    !kv["codec"].empty() && !kv["preset"].empty();
    if (!ok || t.range.first < 0 || t.range.first >= t.range.end || t.range.end > t.frames)
        throw bad("is malformed");
    t.scene = kv["scene"], t.look = kv["look"], t.build = kv["build"];
    t.codec = kv["codec"], t.preset = kv["preset"];
    t.width = int(w), t.height = int(h), t.fps = int(fps), t.crf = int(crf);
    t.key_interval = int(keyint);
    return t;
}

std::string tag_mismatch(const ShardTag& a, const ShardTag& b) {
    const auto differ = [](const char* what, const auto& x, const auto& y) -> std::string {
        if (x == y) return "";
        std::ostringstream s;
        s << what << " " << x << " against " << y;
        return s.str();
    };
    for (const std::string& why :
         {differ("scene", a.scene, b.scene),
          differ("settings (integrator, step or picture switches) look", a.look, b.look),
          differ("build", a.build, b.build), differ("frame count", a.frames, b.frames),
          differ("width", a.width, b.width), differ("height", a.height, b.height),
          differ("fps", a.fps, b.fps), differ("codec", a.codec, b.codec),
          differ("crf", a.crf, b.crf), differ("preset", a.preset, b.preset),
          differ("key interval", a.key_interval, b.key_interval)})
        if (!why.empty()) return why;
    return "";
}

} // namespace tumble::app
