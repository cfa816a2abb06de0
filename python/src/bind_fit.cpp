// Bindings for the fit area (filled in by the module's owner).
#include "bindings.hpp"

namespace corlab::python {
void bind_fit(pybind11::module_& /*m*/) {}
}  // namespace corlab::python
