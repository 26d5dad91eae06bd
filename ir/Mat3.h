// 3×3 matrix helpers for the frame maths of ir/FrameValue.h and runtime/Frame.h (one copy).
#pragma once

namespace ncc {

inline double mat3Det(const double m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// out = m⁻¹ (out may not alias m); m must not be singular (frames refuse zero scale factors).
inline void mat3Inverse(const double m[3][3], double out[3][3]) {
  double d = mat3Det(m);
  out[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / d;
  out[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / d;
  out[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / d;
  out[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / d;
  out[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / d;
  out[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / d;
  out[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / d;
  out[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / d;
  out[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / d;
}

}  // namespace ncc
