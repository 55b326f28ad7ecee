// Precompiled once for vibook_modified (option VIBOOK_PCH): the symbolic engine's units all
// parse GiNaC and Eigen. Nothing here may depend on a macro a source file defines first.
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <ginac/ginac.h>
