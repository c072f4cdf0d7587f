// pmdplan.InputError(ValueError): the library's InputError, the CLI's exit-2 errors. str(error) is
// the CLI's message (after "pmdplan: error: "); .file, .field and .message hold its parts.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan::python {

void bindErrors(py::module_& m) {
  static py::handle inputError;
  inputError = py::exception<InputError>(m, "InputError", PyExc_ValueError).release();
  inputError.attr("__doc__") =
      "Bad input: a file, key or value that is wrong (the CLI's exit-2 errors, same message).\n\n"
      "Attributes: file (may be empty), field (key, column or option), message (what was expected).";
  py::register_exception_translator([](std::exception_ptr pointer) {
    if (!pointer) return;
    try {
      std::rethrow_exception(pointer);
    } catch (const InputError& e) {
      py::object error = inputError(e.what());
      error.attr("file") = e.file();
      error.attr("field") = e.field();
      error.attr("message") = e.message();
      PyErr_SetObject(inputError.ptr(), error.ptr());
    }
  });
}

}  // namespace pmdplan::python
