#pragma once
// Powers of ten that are exact doubles (10^22 is the largest): a number read as an exact integer
// mantissa divided by one of them is the correctly rounded double (the block parser's readNumber
// and its plain-line fast path, PlainLine.cpp).
namespace ncc::iso {
inline constexpr double kExactPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                         1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
}  // namespace ncc::iso
