#pragma once
// A struct's field tied to the parameter that declares it: the one way a struct that holds
// parameters (regional::Scene, render::RenderSettings, the viewer's ViewState) names its fields
// to the table, so that copies between such structs go through the table instead of field by
// field by hand.
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "params/parameter.hpp"

namespace nephele::params {

// An optional number is a value a struct may leave to someone else (a scene's position, given
// by --at or left to its viewpoint): copied from only when it holds a value.
using FieldPointer = std::variant<double*, float*, int*, std::uint32_t*, std::string*, std::optional<double>*>;

struct FieldBinding {
  const Parameter* parameter;
  FieldPointer field;
};

// Copies the value of every parameter that both lists bind from its field in `from` to its field
// in `to`, numbers converted to the target's type (a text to a number, or the reverse, is a
// std::logic_error: one parameter is one kind of value); an empty optional source is skipped.
// Returns how many were copied.
int copy_bound_fields(const std::vector<FieldBinding>& from, const std::vector<FieldBinding>& to);

}  // namespace nephele::params
