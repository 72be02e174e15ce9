// carom for Python (internal): what the binding files share — the parts of the module each adds,
// and the conversion of carom::Vec2 from and to a pair of floats.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <span>

#include "carom/vec2.hpp"
#include "carom/world.hpp"

namespace carom::python {

namespace py = pybind11;

void bind_core(py::module_& m);
void bind_world(py::module_& m);
void bind_scene(py::module_& m);
void bind_science(py::module_& m);
void bind_packing(py::module_& m);
void bind_queries(py::module_& m);
// The table's classes (before bind_world, whose World takes a Table) and World's table methods
// (after it).
void bind_table_types(py::module_& m);
void bind_table_methods(py::module_& m);

// A ball's id as Python holds it: one integer, generation above index; and back.
std::uint64_t id_number(BallId id);
BallId ball_id(std::uint64_t number);
// Contacts as the structured array World.contacts gives.
py::array contacts_array(std::span<const ContactEvent> contacts);
// A World handed to Python as a carom.World.
py::object wrap_world(World&& world);
// The World inside a carom.World (throws a cast error for anything else).
World& unwrap_world(py::handle world);

// A NumPy array of doubles, C-contiguous (converted if need be).
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

}  // namespace carom::python

namespace pybind11::detail {

// A Vec2 from any sequence of two numbers (a tuple, a list, a NumPy array of shape (2,)); to
// Python as a tuple of two floats.
template <>
struct type_caster<carom::Vec2> {
  PYBIND11_TYPE_CASTER(carom::Vec2, const_name("tuple[float, float]"));

  bool load(handle source, bool) {
    if (!isinstance<sequence>(source) && !isinstance<array>(source)) return false;
    const object items = reinterpret_borrow<object>(source);
    if (len(items) != 2) return false;
    try {
      value.x = items[int_(0)].cast<double>();
      value.y = items[int_(1)].cast<double>();
    } catch (const cast_error&) {
      return false;
    }
    return true;
  }

  static handle cast(carom::Vec2 v, return_value_policy, handle) {
    return make_tuple(v.x, v.y).release();
  }
};

}  // namespace pybind11::detail
