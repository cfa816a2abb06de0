// Bindings for the models area (filled in by the module's owner).
#include "bindings.hpp"

namespace corlab::python {
void bind_models(pybind11::module_& /*m*/) {}
}  // namespace corlab::python
