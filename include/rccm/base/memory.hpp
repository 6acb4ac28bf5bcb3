// Memory a run will need, refused up front when the machine does not have it: a mesh or a
// step count too large fails with its estimate, not with bad_alloc after minutes.
#pragma once

#include <string>

namespace rccm {

/// Bytes the machine can give this process now (Linux MemAvailable; a large number elsewhere),
/// at most RCCM_MEMORY_GB gigabytes when that variable is set (a batch job's limit, a shared
/// machine); InputError if it is not a number > 0.
double available_memory();

/// Bytes to assemble and factorize an elastic body of `unknowns` unknowns: the assembly's
/// triplets, the matrix and its Cholesky factor (~2.6 kB per unknown at a million, measured).
double assembly_bytes(double unknowns);

/// "<what> needs about X GB, the machine has Y GB available" when `bytes` exceed what is
/// available; empty when they fit.
std::string memory_shortfall(double bytes, const std::string& what);

/// Throws InputError "`where`: <what> needs about X GB, the machine has Y GB available; <advice>"
/// when `bytes` exceed what is available.
void require_memory(double bytes, const std::string& where, const std::string& what, const std::string& advice);

}  // namespace rccm
