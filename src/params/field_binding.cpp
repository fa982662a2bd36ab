#include "params/field_binding.hpp"

#include <optional>
#include <stdexcept>
#include <type_traits>

namespace nephele::params {

namespace {

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

std::string mixed(const FieldBinding& source) {
  return "copy_bound_fields: '" + std::string(source.parameter->key) +
         "' is bound to a text on one side and a number on the other";
}

}  // namespace

int copy_bound_fields(const std::vector<FieldBinding>& from, const std::vector<FieldBinding>& to) {
  int copied = 0;
  for (const FieldBinding& source : from)
    for (const FieldBinding& target : to) {
      if (source.parameter != target.parameter) continue;
      std::visit(
          [&](auto* in, auto* out) {
            using In = std::remove_pointer_t<decltype(in)>;
            using Out = std::remove_pointer_t<decltype(out)>;
            constexpr bool in_text = std::is_same_v<In, std::string>, out_text = std::is_same_v<Out, std::string>;
            if constexpr (in_text && out_text) {
              *out = *in;
            } else if constexpr (IsOptional<In>::value) {
              if (!in->has_value()) return;
              if constexpr (out_text)
                throw std::logic_error(mixed(source));
              else
                *out = static_cast<Out>(**in);
            } else if constexpr (!in_text && !out_text) {
              *out = static_cast<Out>(*in);
            } else {
              throw std::logic_error(mixed(source));
            }
            ++copied;
          },
          source.field, target.field);
    }
  return copied;
}

}  // namespace nephele::params
