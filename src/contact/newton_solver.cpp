// PLACEHOLDER (issue 17): replaced by its implementation.
#include "rccm/contact/newton_solver.hpp"
