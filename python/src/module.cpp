// carom for Python: the extension module carom._carom. The package carom (python/carom) re-exports
// it with the parts written in Python (GSD trajectories).
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.hpp"
#include "carom/error.hpp"
#include "carom/scene.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_carom, m) {
  m.doc() = "carom: exact continuous collision of moving balls in 2D";
  // The library's refusal of an argument, as the ValueError Python code expects.
  static py::exception<carom::InvalidArgument> invalid_argument(m, "InvalidArgument",
                                                                PyExc_ValueError);
  // A scene that cannot be read: a ValueError carrying where and what.
  static py::exception<carom::SceneError> scene_error(m, "SceneError", PyExc_ValueError);
  // pybind11's translator type takes the exception_ptr by value.
  // NOLINTNEXTLINE(performance-unnecessary-value-param)
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const carom::InvalidArgument& error) {
      py::object instance = py::handle(invalid_argument.ptr())(error.what());
      instance.attr("function") = error.function();
      instance.attr("argument") = error.argument();
      instance.attr("value") = error.value();
      instance.attr("requirement") = error.requirement();
      PyErr_SetObject(invalid_argument.ptr(), instance.ptr());
    } catch (const carom::SceneError& error) {
      const carom::SceneError::Details& d = error.details();
      py::object instance = py::handle(scene_error.ptr())(error.what());
      instance.attr("file") = d.file;
      instance.attr("line") = d.line;
      instance.attr("column") = d.column;
      instance.attr("path") = d.path;
      instance.attr("value") = d.value;
      instance.attr("problem") = d.problem;
      instance.attr("suggestion") = d.suggestion;
      PyErr_SetObject(scene_error.ptr(), instance.ptr());
    }
  });
  m.attr("IMMOVABLE") = carom::kImmovable;
  carom::python::bind_core(m);
  carom::python::bind_table_types(m);
  carom::python::bind_world(m);
  carom::python::bind_table_methods(m);
  carom::python::bind_queries(m);
  carom::python::bind_scene(m);
  carom::python::bind_packing(m);
#ifdef CAROM_PYTHON_GAS
  // Built with the command-line tool, whose gas code these share.
  carom::python::bind_science(m);
#endif
}
