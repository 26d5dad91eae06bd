// Sinumerik SPRINT(format, v1, …): the format descriptors of L3943-L4326 as a typed builtin of
// both engines (ir/Builtins.h).
#pragma once
#include <string>

namespace ncc {

class ValuePool;

// %B %C %D %F %E %G %S %X with an optional width m and precision n (%<m>.<n>F), case-insensitive;
// E and G write the exponent as EX±dd. %P (punched-tape and binary numbers) is an error.
bool strSprint(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error);

}  // namespace ncc
