#pragma once
// One `--set PATH=V1,V2,...` of `tumble sweep`: a field of the scene file and the values it takes.
// PATH is dotted (world.integrator, bodies.1.angular_velocity: numbers index arrays) or a JSON
// pointer (/world/integrator). Values are split at commas outside brackets, braces and quotes,
// so [6,0.05,0.05],[6,0.5,0.5] is two values; each is read as JSON, and one that is not JSON is a
// string (euler means "euler").
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace tumble::app {

struct SweepSet {
    std::string text;              // as given, for messages
    std::string path;              // as given before '='
    std::vector<std::string> keys; // its segments
    std::vector<nlohmann::json> values;
    std::string pointer() const; // "/world/integrator"
};

// Throws io::BadInput naming the --set when it is not PATH=VALUE[,VALUE...].
SweepSet parse_set(const std::string& text);

// Sets the field in `scene` to `value`. Missing objects on the way are created, so that a
// misspelt name reaches the scene reader, which refuses it naming the path with a suggestion
// (`/wrld: unknown field (did you mean "world"?)`). Throws io::BadInput when the path cannot
// exist: an index past the end of an array, a non-number into an array, a field of a number.
void apply_set(nlohmann::json& scene, const SweepSet& set, const nlohmann::json& value,
               const std::string& file);

} // namespace tumble::app
