// pmdplan.InputError(ValueError): the library's InputError, the CLI's exit-2 errors. str(error) is
// the CLI's message (after "pmdplan: error: ") with the field in Python's spelling: a command-line
// flag a library service names ("--tolerance-mm") becomes the Python argument ("tolerance_mm");
// .file, .field and .message hold its parts.
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan::python {
namespace {

/// "--tolerance-mm" -> "tolerance_mm"; any other field as it is.
std::string pythonField(const std::string& field) {
  if (field.size() < 3 || field.compare(0, 2, "--") != 0) return field;
  std::string name = field.substr(2);
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

}  // namespace

void bindErrors(py::module_& m) {
  static py::handle inputError;
  inputError = py::exception<InputError>(m, "InputError", PyExc_ValueError).release();
  inputError.attr("__doc__") =
      "Bad input: a file, key or value that is wrong (the CLI's exit-2 errors, same message, the field as\n"
      "Python names it: tolerance_mm where the CLI says --tolerance-mm).\n\n"
      "Attributes: file (may be empty), field (key, column or option), message (what was expected).";
  py::register_exception_translator([](std::exception_ptr pointer) {
    if (!pointer) return;
    try {
      std::rethrow_exception(pointer);
    } catch (const InputError& raised) {
      const InputError e(raised.file(), pythonField(raised.field()), raised.message());
      py::object error = inputError(e.what());
      error.attr("file") = e.file();
      error.attr("field") = e.field();
      error.attr("message") = e.message();
      PyErr_SetObject(inputError.ptr(), error.ptr());
    }
  });
}

}  // namespace pmdplan::python
