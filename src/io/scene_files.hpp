#pragma once
// Scene files of `nephele render --scene`: strict JSON whose keys, defaults and ranges come from
// the parameter table (params::scene); unknown keys and wrong types are errors naming the file
// and the key (regional::SceneError, exit code 2). Weather paths resolve against the file's folder.
#include <string>

#include "regional/scene.hpp"

namespace nephele::io {

regional::Scene read_scene_file(const std::string& path);
regional::Scene parse_scene(const std::string& json_text, const std::string& source_name,
                            const std::string& base_directory);

}  // namespace nephele::io
