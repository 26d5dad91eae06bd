// The FRAME builtins of the expression language (ir/Builtins.cpp lists them in its table; the
// rules are in ir/FrameValue.h). Typed-builtin convention of ir/Builtins.h: raw argument values,
// false with `error` set on a run-time error.
#pragma once
#include <string>

namespace ncc {
class ValuePool;

#define NCC_FRAMEFN(NAME) bool NAME(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error)
NCC_FRAMEFN(frameCtrans);    // CTRANS(ax, v, …): coarse offsets
NCC_FRAMEFN(frameCfine);     // CFINE(ax, v, …): fine offsets
NCC_FRAMEFN(frameCrot);      // CROT(ax, deg, …): rotation about X Y Z (RPY)
NCC_FRAMEFN(frameCrots);     // CROTS(ax, deg, …): rotation by solid angles
NCC_FRAMEFN(frameCscale);    // CSCALE(ax, f, …): scale factors (negative mirrors)
NCC_FRAMEFN(frameCmirror);   // CMIRROR(ax, …)
NCC_FRAMEFN(frameInvframe);  // INVFRAME(f)
NCC_FRAMEFN(frameChainFn);   // FRAME_CHAIN(a, b): Sinumerik a : b
NCC_FRAMEFN(frameGet);       // FRAME_GET(f, ax, comp): F[X, TR]
NCC_FRAMEFN(frameSet);       // FRAME_SET(f, ax, comp, v): F with F[X, TR] = v
#undef NCC_FRAMEFN

}  // namespace ncc
