#include "app/regression/golden_renderers.h"

#include "app/scene/field_table.h"
#include "app/scene/input_file.h"
#include "io/atomic_file.h"

#include <fstream>

namespace tumble::app {
namespace {

const Table& identity_table() {
    static const Table t{"gl",
                         "the GL renderer that drew a golden",
                         {{"gl_renderer", types::string(), "GL_RENDERER", true},
                          {"gl_version", types::string(), "GL_VERSION", true},
                          {"scene_content_hash", types::string(),
                           "the content hash of the scene the image was drawn from", false}}};
    return t;
}

const Table& record_table() {
    static const Table t{
        "golden_renderers",
        "which GL renderer drew each golden image",
        {{"format_version", types::integer(1, 1), "format version 1", true},
         {"images", types::map_of(types::object(identity_table), "the renderer of an image"),
          "image file -> renderer", true}}};
    return t;
}

} // namespace

std::string GlIdentity::describe() const {
    return known() ? "\"" + renderer + "\" / \"" + version + "\"" : "an unrecorded renderer";
}

GoldenRenderers GoldenRenderers::load(const std::filesystem::path& goldens) {
    GoldenRenderers out;
    out.path_ = goldens / kFileName;
    std::error_code ec;
    if (!std::filesystem::exists(out.path_, ec)) return out;
    const nlohmann::json root =
        parse_json(read_input_file(out.path_, "golden record"), out.path_.string());
    ObjectReader r(JsonReader(root, out.path_.string(), ""), record_table());
    r.field("format_version").integer();
    const FieldValue images = r.field("images");
    if (!images.value().is_object()) images.fail("expected an object of image file names");
    for (auto it = images.value().begin(); it != images.value().end(); ++it) {
        const JsonReader entry(it.value(), out.path_.string(),
                               images.reader().path() + "/" + json_pointer_segment(it.key()));
        ObjectReader e(entry, identity_table());
        Entry& kept = out.images_[it.key()];
        kept.gl = {e.field("gl_renderer").string(), e.field("gl_version").string()};
        if (auto h = e.optional("scene_content_hash")) kept.scene_hash = h->string();
        e.finish();
    }
    r.finish();
    return out;
}

GlIdentity GoldenRenderers::of(const std::string& image_file) const {
    const auto it = images_.find(image_file);
    return it == images_.end() ? GlIdentity{} : it->second.gl;
}

std::string GoldenRenderers::scene_hash_of(const std::string& image_file) const {
    const auto it = images_.find(image_file);
    return it == images_.end() ? std::string() : it->second.scene_hash;
}

void GoldenRenderers::set(const std::string& image_file, const GlIdentity& gl,
                          const std::string& scene_hash) {
    images_[image_file] = {gl, scene_hash};
}

void GoldenRenderers::save() const {
    nlohmann::json images = nlohmann::json::object();
    for (const auto& [file, e] : images_) {
        images[file] = {{"gl_renderer", e.gl.renderer}, {"gl_version", e.gl.version}};
        if (!e.scene_hash.empty()) images[file]["scene_content_hash"] = e.scene_hash;
    }
    const nlohmann::json root = {{"format_version", 1}, {"images", images}};
    io::AtomicFile file(path_);
    std::ofstream out(file.temp_path(), std::ios::binary);
    out << root.dump(2) << "\n";
    out.close();
    if (!out) throw io::FileError("cannot write '" + path_.string() + "'");
    file.commit();
}

} // namespace tumble::app
