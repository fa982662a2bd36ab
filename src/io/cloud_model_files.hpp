#pragma once
// Cloud model files (scenes/*.cloud.json) of the implicit modeller (docs/model.md).
#include <string>

#include "model/cloud_model.hpp"

namespace nephele::io {

// Strict cloud model files (scenes/*.cloud.json): unknown or duplicate keys, wrong types and
// values outside the table's ranges are refused with the key named.
model::CloudModel parse_cloud_model(const std::string& text, const std::string& source);
// `option` is what the user typed to name the file (--scene of model, --model of view).
model::CloudModel read_cloud_model(const std::string& path, const std::string& option = "--scene");
// The model as a cloud model file (the sidecar records it; parse_cloud_model reads it back).
std::string write_cloud_model(const model::CloudModel& model);

}  // namespace nephele::io
