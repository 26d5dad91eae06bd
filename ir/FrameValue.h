// FRAME values (Sinumerik `DEF FRAME`, SIN-TYP-07, SIN-FRM-01…09), shared by both engines and the
// executor. A frame maps a child (inner) coordinate system onto its parent (outer) one:
//
//   X Y Z:  x_parent = TR + FI + L · x_child        L = R · S · M (rotation, scale, mirror)
//   A B C:  a_parent = TR + FI + f · a_child        f = scale, negative when mirrored
//
// and `A : B` (FRAME_CHAIN) is A ∘ B: B is expressed in A's coordinate system (the manual's "left
// to right, each in the system the previous one produced"). The matrix is kept whole, so chains
// are exact; the components a program reads (TR FI RT SC MI) are a decomposition of it, with the
// rotation angles of RT in the RPY convention R = Rz(γ)·Ry(β)·Rx(α) (MD10600 = 1) and the ranges
// X and Z −180…180, Y −90…90. A frame whose matrix has no such decomposition (a rotation combined
// with unequal scale factors) can still be chained and applied, but reading or writing RT SC MI
// of it is an error, never an approximation.
//
// Values are NaN-boxed handles (kFrameTag | i, ir/Value.h) into the run's FramePool; handle 0 is
// the identity (the value of a new FRAME variable). Lengths are numbers as programmed: the
// executor applies them in the unit that is active when a frame takes effect.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace ncc {

constexpr int kFrameAxes = 6;  // X Y Z A B C (the axes the executor models)
enum class FrameComp : uint8_t { TR, FI, RT, SC, MI };

struct FrameValue {
  double L[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  double coarse[kFrameAxes] = {}, fine[kFrameAxes] = {};
  double rotary[3] = {1, 1, 1};  // A B C: f

  bool operator==(const FrameValue &o) const;
  bool identity() const { return *this == FrameValue{}; }
  double offset(int axis) const { return coarse[axis] + fine[axis]; }
};

// The components of a frame, as programs read and write them.
struct FrameParts {
  double tr[kFrameAxes] = {}, fi[kFrameAxes] = {};
  double rt[3] = {};  // degrees about X, Y, Z
  double sc[kFrameAxes] = {1, 1, 1, 1, 1, 1};
  bool mi[kFrameAxes] = {};
};

// A : B.
FrameValue frameChain(const FrameValue &a, const FrameValue &b);
// The frame F⁻¹ with F : F⁻¹ = identity (INVFRAME).
FrameValue frameInverse(const FrameValue &f);
// The decomposition; false (with `error`) when the matrix has none.
bool frameDecompose(const FrameValue &f, FrameParts &out, std::string &error);
FrameValue frameCompose(const FrameParts &p);
// The rotation R = Rz(z)·Ry(y)·Rx(x), degrees.
void frameRotation(double x, double y, double z, double R[3][3]);

// The rotation of Sinumerik's solid angles (ROTS, AROTS, CROTS), degrees about X Y Z with
// `given` the angles programmed. One angle is the rotation about that axis (as ROT). Two span
// a plane with the third axis t (X Y -> Z, Y Z -> X, Z X -> Y: first f, second s): the angle at
// s turns f about s onto the line where the new plane meets the f-t plane, the angle at f turns s
// about f onto the line where it meets the s-t plane; the new f is the first line (it stays in
// the old f-t plane) and the new t the plane's normal (Siemens function manual K2, "Frame
// rotations with solid angles"). False with `error` for three angles or a pair that spans no
// plane (both 90°).
bool frameSolidRotation(const bool given[3], const double angle[3], double R[3][3], std::string &error);

// "X".."C" (any case) -> 0..5; false for another name.
bool frameAxis(std::string_view name, int &axis);
bool frameComp(std::string_view name, FrameComp &out);
const char *frameAxisName(int axis);
// A readable form for messages: "TR X10 Y20 RT Z45 SC X2 MI Y" ("identity" for the identity; a
// matrix form when there is no decomposition).
std::string frameText(const FrameValue &f);

// The frames of one run: interned (equal frames share a handle), never freed before the run ends.
constexpr uint32_t kMaxPoolFrames = 200000;
class FramePool {
public:
  FramePool();
  bool intern(const FrameValue &f, double &out, std::string &error);
  // The frame of a handle; the identity for anything that is not a frame handle.
  const FrameValue &get(double v) const;

private:
  std::vector<FrameValue> frames_;
  std::unordered_multimap<uint64_t, uint32_t> index_;  // content hash -> index
};

}  // namespace ncc
