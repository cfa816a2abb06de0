// Bindings for the study area (filled in by the module's owner).
#include "bindings.hpp"

namespace corlab::python {
void bind_study(pybind11::module_& /*m*/) {}
}  // namespace corlab::python
