// ParamValue (parser/expression.hpp): the int, float or str value of a parameter.
#include <utility>

#include "parser/expression.hpp"
#include "parser/expression/python_repr.hpp"

namespace clinch {

using expression_detail::float_repr;
using expression_detail::string_repr;

ParamValue ParamValue::make_int(std::int64_t value) {
  ParamValue v;
  v.kind = Kind::Int;
  v.i = value;
  return v;
}

ParamValue ParamValue::make_float(double value) {
  ParamValue v;
  v.kind = Kind::Float;
  v.f = value;
  return v;
}

ParamValue ParamValue::make_string(std::string value) {
  ParamValue v;
  v.kind = Kind::String;
  v.s = std::move(value);
  return v;
}

double ParamValue::as_double() const {
  switch (kind) {
    case Kind::Int:
      return static_cast<double>(i);
    case Kind::Float:
      return f;
    case Kind::String:
      return 0.0;
  }
  return 0.0;
}

std::string ParamValue::to_display() const {
  switch (kind) {
    case Kind::Int:
      return std::to_string(i);
    case Kind::Float:
      return float_repr(f);
    case Kind::String:
      return string_repr(s);
  }
  return {};
}

}  // namespace clinch
