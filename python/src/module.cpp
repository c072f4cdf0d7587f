// pmdplan._core: the compiled part of the Python package `pmdplan` (pmdplan/__init__.py
// re-exports it; pmdplan/__init__.pyi holds the types).
#include "bindings.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "pmdplan: human-like motion planning for robot hand-arm systems with principal motion directions";
  using namespace pmdplan::python;
  bindErrors(m);
  bindRobotAndTask(m);
  bindCollision(m);
  bindSynergies(m);
  bindPlannerSettings(m);
  bindPlanning(m);
  bindValidation(m);
}
