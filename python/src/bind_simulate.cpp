// Bindings for the simulate area (filled in by the module's owner).
#include "bindings.hpp"

namespace corlab::python {
void bind_simulate(pybind11::module_& /*m*/) {}
}  // namespace corlab::python
