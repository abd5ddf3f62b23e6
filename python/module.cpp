// The Python module hocav (docs/python.md): hocav._hocav, wrapped by hocav/__init__.py.
#include "base/error.hpp"
#include "binding.hpp"

PYBIND11_MODULE(_hocav, module) {
  namespace py = pybind11;
  module.doc() = "hocav: curved (P2) metric-based mesh adaptation";
  // Raised with the message the command line prints after "hocav: ".
  py::register_exception<hocav::Error>(module, "Error", PyExc_RuntimeError);
  hocav::python::bind_mesh(module);
  hocav::python::bind_metrics(module);
  hocav::python::bind_jobs(module);
  module.attr("__version__") = HOCAV_VERSION;
}
