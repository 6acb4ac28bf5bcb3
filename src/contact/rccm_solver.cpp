// PLACEHOLDER (issue 17): replaced by its implementation.
#include "rccm/contact/rccm_solver.hpp"
