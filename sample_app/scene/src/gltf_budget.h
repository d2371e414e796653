#pragma once
// The model's work budget (scene/gltf_limits.h; private to the loader): what the file's own
// counts will expand to, added up from the raw JSON before tinygltf parses it and before any
// accessor is read, so a refusal costs the parse of the JSON and nothing proportional to the
// claimed size.

#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include "scene/gltf_limits.h"

namespace ocean_scene::gltf {

// False with one line naming every limit the file exceeds, with its count and the limit
// ("10000000000 triangles after instancing (limit 4194304), ..."), and how to raise them.
// Counts that are malformed (an index to nothing, a count that is not a number) add nothing
// here: the checks that follow refuse them. Needs integersFit and the preflight's
// non-negative checks to have passed.
bool withinBudget(const nlohmann::json& root, const GltfLimits& limits, std::string& error);

// The JSON's own limits, from its text through a SAX pass that builds nothing (a file of a
// million nodes costs 0.3 s to parse into a document and 0.1 s more to free, this a fraction;
// 50 M zeros took 9.7 GB as documents): its values (limits.jsonValues, the count stopping
// there) and the "nodes" limit. A duplicate object key is refused here too, by its JSON path.
// True (nothing said) when the text is not valid JSON: the document's parse reports that.
bool jsonWithinBudget(std::string_view text, const GltfLimits& limits, std::string& error);

// "the model exceeds the work budget: <over>; refused before it is expanded (raise with
// <limits.raiseOption> <keys>)": every budget refusal's sentence.
std::string refusal(const std::string& over, const std::string& keys, const GltfLimits& limits);

}  // namespace ocean_scene::gltf
