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

// The "nodes" limit alone, from the JSON text through a SAX pass that builds nothing: a file of
// a million nodes costs 0.3 s to parse into a document and 0.1 s more to free, this a fraction.
// True (nothing said) when the text is not valid JSON: the document's parse reports that.
bool nodesWithinBudget(std::string_view text, const GltfLimits& limits, std::string& error);

}  // namespace ocean_scene::gltf
