// The programmable frame: the part of the frame chain a program sets with ISO G52 (local
// shift), G68 (rotation, 2-D or 3-D, two levels), G51 (scaling, negative factors mirror) and
// G51.1 (mirror about a position). Later the Sinumerik TRANS/ROT/SCALE/MIRROR and Heidenhain
// datum/rotation/scaling cycles land on the same slots.
//
// The whole chain, program side first (runtime/ExecutorImpl.h):
//   program -> mirror -> scale -> rotation (level 2, then level 1) -> local shift   [this file]
//           -> G92 -> XY rotation of the work offset (G10 L2 R) -> G54..G59.3 -> tool length
// which is the Fanuc order (mirror, then scaling, then rotation; manual 808D 2.4.2.3-4) followed
// by rs274's (machine = Rz(program + G92) + G5x + tool length).
#pragma once
#include "ir/MotionIR.h"
#include "runtime/Geometry.h"

#include <algorithm>

namespace ncc {

// p' = m p + t on X Y Z (rotary axes are not transformed by a frame).
struct Affine {
  double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Vec3 t{};

  Vec3 apply(const Vec3 &p) const;
  Vec3 applyLinear(const Vec3 &v) const;
  // outer ∘ this: first this, then outer.
  Affine then(const Affine &outer) const;
  Affine inverse() const;
  bool linearIdentity() const;
  double det() const;

  static Affine rotation(Vec3 axis, double degrees, const Vec3 &centre);  // axis: any length > 0
  static Affine scaling(const Vec3 &factors, const Vec3 &centre);
};

struct ProgrammableFrame {
  // Slots (program side first). Local is a shift of all six axes.
  Vec3 mirrorAxes{};      // 1 where the axis is mirrored
  Vec3 mirrorAt{};        // about this position (program coordinates)
  bool scaleOn = false;
  Vec3 scaleFactors{1, 1, 1}, scaleCentre{};
  int rotationLevels = 0;    // 0, 1 or 2 stacked G68 rotations
  Affine rotation[2];        // level 1 (outer, the first G68), level 2 (inner)
  AxisVec local{};
  // The 808D's G72.1/G72.2 contour repetition (innermost, on the program side): copy k runs with
  // k times the step, a rotation of copyAngle degrees about copyAxis through copyCentre or the
  // shift copyShift (mm). copyOn from G72.x's start to its end.
  bool copyOn = false;
  int copyIndex = 0;
  double copyAngle = 0;
  Vec3 copyAxis{}, copyCentre{}, copyShift{};
  Affine copy;  // the transform of copy copyIndex (update() sets it)
  // The tilted working plane (Heidenhain cycle 19 / PLANE, runtime/ExecutorPlane.cpp): the
  // outermost slot, a rotation about the datum active at its definition (`tiltPivot`, the local
  // shift then), so a shift defined before the tilt moves the pivot and one defined after it
  // (local - tiltPivot) moves the tilted system along its own axes.
  bool tiltOn = false;
  Affine tilt;  // the rotation about tiltPivot (update() applies it last)
  double tiltMatrix[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // its linear part: tilted axes in columns
  Vec3 tiltPivot{};

  // The composite of the linear slots and the local shift, and its inverse (update() sets them).
  Affine composite, inverseComposite;
  bool linear = false;  // a mirror, scaling, rotation or tilt is active (else only the local shift)

  void update();
  // The same transform (composite and local shift) as `o`, exactly: what was written still holds.
  bool sameTransform(const Affine &c, const AxisVec &l) const {
    return composite.t == c.t && local == l && std::equal(&composite.m[0][0], &composite.m[0][0] + 9, &c.m[0][0]);
  }
  // The linear part is a rotation times one scale factor (a mirror allowed): circles stay circles.
  bool similar() const;
  bool mirrorOn() const { return mirrorAxes[0] || mirrorAxes[1] || mirrorAxes[2]; }
  void clearMirror() { mirrorAxes = {}, mirrorAt = {}; }
  void clearScale() { scaleOn = false, scaleFactors = {1, 1, 1}, scaleCentre = {}; }
  void clearRotation() { rotationLevels = 0, rotation[0] = rotation[1] = Affine{}; }
  void clearCopy() { copyOn = false, copyIndex = 0, copyAngle = 0, copyAxis = copyCentre = copyShift = {}; }
  void clearTilt() { tiltOn = false, tilt = Affine{}, tiltPivot = {}, tiltMatrix[0][0] = tiltMatrix[1][1] = tiltMatrix[2][2] = 1,
                     tiltMatrix[0][1] = tiltMatrix[0][2] = tiltMatrix[1][0] = tiltMatrix[1][2] = tiltMatrix[2][0] = tiltMatrix[2][1] = 0; }
  // Only the tilt (and the local shift) is active: no mirror, scaling, rotation or copy inside it.
  bool onlyTilt() const { return tiltOn && !mirrorOn() && !scaleOn && rotationLevels == 0 && !copyOn; }

  // Program coordinates -> the input of the G92 slot, and back (all six axes; A B C shift only).
  AxisVec out(const AxisVec &program) const;
  AxisVec in(const AxisVec &shifted) const;
};

}  // namespace ncc
