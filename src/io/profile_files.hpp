#pragma once
// The coverage profile CSV of --profile FILE (docs/formats.md, "Profile CSV"): rows
// `latitude_deg,fraction`, an optional header of those two names, `#` comment lines and blank
// lines; latitudes strictly increasing within [-90, 90], fractions within [0, 1]. Beyond the
// first and last row the fraction stays that row's (docs/climate.md).
#include <string>

#include "cover/latitude_profile.hpp"

namespace nephele::io {

// Throws core::InputError naming the file, the line, the field and the allowed range.
cover::LatitudeProfile read_profile_csv(const std::string& path);
// The same from text already read (`name` is the file shown in errors and the sidecar).
cover::LatitudeProfile parse_profile_csv(const std::string& text, const std::string& name);

// --profile's value: earth, flat, or a CSV file.
cover::LatitudeProfile profile_from_option(const std::string& value);

}  // namespace nephele::io
