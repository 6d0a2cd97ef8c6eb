#include "app/cluster/checkpoint.h"

#include "app/cluster/byte_codec.h"
#include "app/scene/content_hash.h"
#include "app/scene/input_file.h"
#include "io/atomic_file.h"
#include "physics/state_fields.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace tumble::app {

namespace {

constexpr std::string_view kMagic = "TUMBLECK";

// One element of a State field, as bytes (and back): numbers as themselves, vectors and
// quaternions as their doubles in storage order, a contact point member by member.
template <class T>
requires std::is_arithmetic_v<T>
void put(ByteWriter& w, T v) {
    w.number(v);
}
void put(ByteWriter& w, const physics::Vec3& v) {
    for (int i = 0; i < 3; ++i) w.number(v[i]);
}
void put(ByteWriter& w, const physics::Quat& q) {
    for (int i = 0; i < 4; ++i) w.number(q.coeffs()[i]);
}
void put(ByteWriter& w, const physics::CachedPoint& p) {
    physics::for_each_field(p, [&](const char*, const auto& member) { put(w, member); });
}

template <class T>
requires std::is_arithmetic_v<T>
void get(ByteReader& r, T& v) {
    v = r.number<T>();
}
void get(ByteReader& r, physics::Vec3& v) {
    for (int i = 0; i < 3; ++i) v[i] = r.number<double>();
}
void get(ByteReader& r, physics::Quat& q) {
    for (int i = 0; i < 4; ++i) q.coeffs()[i] = r.number<double>();
}
void get(ByteReader& r, physics::CachedPoint& p) {
    physics::for_each_field(p, [&](const char*, auto& member) { get(r, member); });
}

// Bytes one element of T takes in the file (what put() writes for it).
template <class T>
requires std::is_arithmetic_v<T> std::uint32_t bytes_of(const T&) {
    return sizeof(T);
}
std::uint32_t bytes_of(const physics::Vec3&) {
    return 3 * sizeof(double);
}
std::uint32_t bytes_of(const physics::Quat&) {
    return 4 * sizeof(double);
}
std::uint32_t bytes_of(const physics::CachedPoint& p) {
    std::uint32_t n = 0;
    physics::for_each_field(p, [&](const char*, const auto& member) { n += bytes_of(member); });
    return n;
}
template <class T>
std::uint32_t element_bytes() {
    static const T sample{}; // only its type is looked at
    return bytes_of(sample);
}

template <class T>
struct Elements {
    using type = T; // a scalar field (the step counter) is one element
    static std::size_t count(const T&) { return 1; }
};
template <class T>
struct Elements<std::vector<T>> {
    using type = T;
    static std::size_t count(const std::vector<T>& v) { return v.size(); }
};

template <class T>
void put_field(ByteWriter& w, const char* name, const T& field) {
    using E = typename Elements<T>::type;
    w.text(name);
    w.number(static_cast<std::uint64_t>(Elements<T>::count(field)));
    w.number(element_bytes<E>());
    if constexpr (std::is_same_v<T, E>)
        put(w, field);
    else
        for (const E& e : field) put(w, e);
}

template <class T>
void get_field(ByteReader& r, const char* name, T& field) {
    using E = typename Elements<T>::type;
    const std::string found = r.text();
    if (found != name)
        throw TruncatedBytes("the state field at byte " + std::to_string(r.offset()) + " is '" +
                             found + "', expected '" + name + "'");
    const auto count = r.number<std::uint64_t>();
    const auto bytes = r.number<std::uint32_t>();
    const std::string what = std::string("the field ") + name;
    if (bytes != element_bytes<E>())
        throw TruncatedBytes(what + " has elements of " + std::to_string(bytes) +
                             " bytes, expected " + std::to_string(element_bytes<E>()));
    if (count > r.left() / bytes)
        throw TruncatedBytes(what + " claims " + std::to_string(count) +
                             " elements, more than the file holds");
    if constexpr (std::is_same_v<T, E>) {
        if (count != 1) throw TruncatedBytes(what + " has " + std::to_string(count) + " values");
        get(r, field);
    } else {
        field.resize(count);
        for (E& e : field) get(r, e);
    }
}

void put_header(ByteWriter& w, const CheckpointHeader& h) {
    w.number(h.scene_hash);
    w.text(h.build);
    w.text(h.integrator);
    w.number(h.h);
    w.number(static_cast<std::int32_t>(h.fps));
    w.number(static_cast<std::int32_t>(h.steps_per_frame));
    w.number(h.frame);
    w.number(h.bodies);
}

CheckpointHeader get_header(ByteReader& r) {
    CheckpointHeader h;
    h.scene_hash = r.number<std::uint64_t>();
    h.build = r.text();
    h.integrator = r.text();
    h.h = r.number<double>();
    h.fps = r.number<std::int32_t>();
    h.steps_per_frame = r.number<std::int32_t>();
    h.frame = r.number<std::int64_t>();
    h.bodies = r.number<std::int64_t>();
    return h;
}

std::uint64_t checksum(std::string_view bytes) {
    ContentHash hash;
    hash.add(bytes);
    return hash.value();
}

constexpr std::size_t kFieldCount = 14; // for_each_field(State) lists 14 fields

} // namespace

std::string encode_checkpoint(const CheckpointHeader& header, const physics::State& state) {
    ByteWriter w;
    w.raw(kMagic);
    w.number(kCheckpointVersion);
    put_header(w, header);
    w.number(static_cast<std::uint32_t>(kFieldCount));
    std::size_t fields = 0;
    physics::for_each_field(state, [&](const char* name, const auto& field) {
        put_field(w, name, field);
        ++fields;
    });
    if (fields != kFieldCount) throw std::logic_error("checkpoint: kFieldCount is out of date");
    w.number(checksum(w.bytes()));
    return w.bytes();
}

Checkpoint decode_checkpoint(const std::string& bytes, const std::string& file) {
    const auto fail = [&](const std::string& why) -> CheckpointError {
        return CheckpointError(file + ": not a checkpoint this tumble can read: " + why);
    };
    if (!std::string_view(bytes).starts_with(kMagic))
        throw fail("it does not start with \"TUMBLECK\" (checkpoints are written by `tumble "
                   "simulate --checkpoint-every K`)");
    try {
        ByteReader r(bytes);
        r.raw(kMagic.size(), "the magic");
        if (const auto v = r.number<std::uint32_t>(); v != kCheckpointVersion)
            throw fail("format version " + std::to_string(v) + ", this tumble reads version " +
                       std::to_string(kCheckpointVersion));
        if (bytes.size() < r.offset() + 8) throw TruncatedBytes("no checksum at the end");
        const std::string_view body(bytes.data(), bytes.size() - 8);
        ByteReader tail(std::string_view(bytes).substr(body.size()));
        if (tail.number<std::uint64_t>() != checksum(body))
            throw fail("its checksum does not match its contents (the file is damaged or was "
                       "cut short)");
        Checkpoint c;
        c.header = get_header(r);
        if (const auto n = r.number<std::uint32_t>(); n != kFieldCount)
            throw fail(std::to_string(n) + " state fields, expected " +
                       std::to_string(kFieldCount));
        physics::for_each_field(c.state,
                                [&](const char* name, auto& field) { get_field(r, name, field); });
        if (r.left() != 8) throw TruncatedBytes("bytes left over after the last field");
        return c;
    } catch (const TruncatedBytes& e) {
        throw fail(e.what());
    }
}

void write_checkpoint(const std::filesystem::path& path, const CheckpointHeader& header,
                      const physics::State& state) {
    const std::string bytes = encode_checkpoint(header, state);
    io::AtomicFile file(path);
    std::FILE* f = std::fopen(file.temp_path().c_str(), file.fopen_mode());
    if (!f)
        throw std::runtime_error("cannot write '" + path.string() + "': " + std::strerror(errno));
    const bool wrote = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    const int write_errno = errno;
    const bool closed = std::fclose(f) == 0;
    if (!wrote || !closed)
        throw std::runtime_error("cannot write '" + path.string() +
                                 "': " + std::strerror(wrote ? errno : write_errno));
    try {
        file.commit();
    } catch (const io::FileError& e) {
        throw std::runtime_error(e.what());
    }
}

Checkpoint read_checkpoint(const std::filesystem::path& path) {
    return decode_checkpoint(read_input_file(path, "checkpoint"), path.string());
}

std::string header_mismatch(const CheckpointHeader& found, const CheckpointHeader& run) {
    if (found.scene_hash != run.scene_hash)
        return "it was made from another scene (scene hash " +
               ContentHash::to_hex(found.scene_hash) + ", this run's is " +
               ContentHash::to_hex(run.scene_hash) + ")";
    if (found.build != run.build)
        return "it was made by another build of tumble (build " + found.build + ", this one is " +
               run.build + "); states are bit-identical only within one build";
    if (found.integrator != run.integrator)
        return "it was made with integrator " + found.integrator + ", this run uses " +
               run.integrator;
    char steps[160];
    std::snprintf(steps, sizeof steps, "step %.17g s at %d fps, this run's is %.17g s at %d fps",
                  found.h, found.fps, run.h, run.fps);
    if (found.h != run.h || found.fps != run.fps || found.steps_per_frame != run.steps_per_frame)
        return std::string("it was made with ") + steps;
    if (found.bodies != run.bodies)
        return "it holds " + std::to_string(found.bodies) + " bodies, this run's scene has " +
               std::to_string(run.bodies);
    return "";
}

} // namespace tumble::app
