// Calls the numerical mju_ utilities of the 2.2.2 API on deterministic pseudo-random inputs and
// prints every result ("name#case v1 v2 ..." with %.17g). Compiled against Debian's MuJoCo and
// against ours; tests/mju.rs compares the two outputs number by number.

#include <math.h>
#include <stdio.h>
#include <string.h>

#include <mujoco/mujoco.h>

#define NCASE 100

static unsigned long long state = 12345;

// uniform in [-1, 1)
static double rnd(void) {
  state = state * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(state >> 11) / 9007199254740992.0 * 2 - 1;
}

static void fill(mjtNum* v, int n) {
  for (int i = 0; i < n; i++) v[i] = rnd();
}

static void unit_quat(mjtNum q[4]) {
  fill(q, 4);
  double s = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (int i = 0; i < 4; i++) q[i] /= s;
}

// a rotation matrix, computed here from a unit quaternion
static void rot_mat(mjtNum m[9]) {
  mjtNum q[4];
  unit_quat(q);
  double a = q[0], b = q[1], c = q[2], d = q[3];
  m[0] = a * a + b * b - c * c - d * d; m[1] = 2 * (b * c - a * d);         m[2] = 2 * (b * d + a * c);
  m[3] = 2 * (b * c + a * d);         m[4] = a * a - b * b + c * c - d * d; m[5] = 2 * (c * d - a * b);
  m[6] = 2 * (b * d - a * c);         m[7] = 2 * (c * d + a * b);         m[8] = a * a - b * b - c * c + d * d;
}

// a symmetric positive definite n x n matrix B B' + n I, computed here
static void spd(mjtNum* m, int n) {
  mjtNum b[64];
  fill(b, n * n);
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < n; j++) {
      double s = i == j ? n : 0;
      for (int k = 0; k < n; k++) s += b[i * n + k] * b[j * n + k];
      m[i * n + j] = s;
    }
  }
}

static void out(const char* name, int k, const mjtNum* v, int n) {
  printf("%s#%d", name, k);
  for (int i = 0; i < n; i++) printf(" %.17g", v[i]);
  printf("\n");
}

static void out1(const char* name, int k, double v) { out(name, k, &v, 1); }

int main(void) {
  mjtNum a[64], b[64], c[64], d[64], r[64], r2[64], s;
  for (int k = 0; k < NCASE; k++) {
    // 3-vectors
    fill(a, 3); fill(b, 3); s = rnd() * 3;
    mju_scl3(r, a, s); out("mju_scl3", k, r, 3);
    mju_add3(r, a, b); out("mju_add3", k, r, 3);
    mju_sub3(r, a, b); out("mju_sub3", k, r, 3);
    mju_copy3(r, a); mju_addTo3(r, b); out("mju_addTo3", k, r, 3);
    mju_copy3(r, a); mju_subFrom3(r, b); out("mju_subFrom3", k, r, 3);
    mju_copy3(r, a); mju_addToScl3(r, b, s); out("mju_addToScl3", k, r, 3);
    mju_addScl3(r, a, b, s); out("mju_addScl3", k, r, 3);
    mju_copy3(r, a); r[3] = mju_normalize3(r); out("mju_normalize3", k, r, 4);
    out1("mju_norm3", k, mju_norm3(a));
    out1("mju_dot3", k, mju_dot3(a, b));
    out1("mju_dist3", k, mju_dist3(a, b));
    mju_cross(r, a, b); out("mju_cross", k, r, 3);
    rot_mat(c);
    mju_rotVecMat(r, a, c); out("mju_rotVecMat", k, r, 3);
    mju_rotVecMatT(r, a, c); out("mju_rotVecMatT", k, r, 3);

    // n-vectors and matrices
    int n = 1 + k % 7, m = 1 + (k / 7) % 5, p = 1 + (k / 3) % 4;
    fill(a, n * m); fill(b, n * m); fill(d, 64); s = rnd();
    out1("mju_sum", k, mju_sum(a, n));
    out1("mju_L1", k, mju_L1(a, n));
    mju_scl(r, a, s, n); out("mju_scl", k, r, n);
    mju_add(r, a, b, n); out("mju_add", k, r, n);
    mju_sub(r, a, b, n); out("mju_sub", k, r, n);
    mju_copy(r, a, n); mju_addTo(r, b, n); out("mju_addTo", k, r, n);
    mju_copy(r, a, n); mju_subFrom(r, b, n); out("mju_subFrom", k, r, n);
    mju_copy(r, a, n); mju_addToScl(r, b, s, n); out("mju_addToScl", k, r, n);
    mju_addScl(r, a, b, s, n); out("mju_addScl", k, r, n);
    mju_copy(r, a, n); r[n] = mju_normalize(r, n); out("mju_normalize", k, r, n + 1);
    out1("mju_norm", k, mju_norm(a, n));
    out1("mju_dot", k, mju_dot(a, b, n));
    mju_mulMatVec(r, a, b, n, m); out("mju_mulMatVec", k, r, n);
    mju_mulMatTVec(r, a, b, n, m); out("mju_mulMatTVec", k, r, m);
    mju_transpose(r, a, n, m); out("mju_transpose", k, r, n * m);
    mju_mulMatMat(r, a, d, n, m, p); out("mju_mulMatMat", k, r, n * p);
    mju_mulMatMatT(r, a, d, n, m, p); out("mju_mulMatMatT", k, r, n * p);
    mju_mulMatTMat(r, a, d, n, m, p); out("mju_mulMatTMat", k, r, m * p);
    fill(c, n);
    mju_sqrMatTD(r, a, c, n, m); out("mju_sqrMatTD", k, r, m * m);
    mju_sqrMatTD(r, a, NULL, n, m); out("mju_sqrMatTD(null)", k, r, m * m);

    // spatial vectors
    fill(a, 6); fill(b, 3); fill(d, 3); rot_mat(c);
    mju_transformSpatial(r, a, 0, b, d, c); out("mju_transformSpatial(motion)", k, r, 6);
    mju_transformSpatial(r, a, 1, b, d, c); out("mju_transformSpatial(force)", k, r, 6);
    mju_transformSpatial(r, a, 1, b, d, NULL); out("mju_transformSpatial(norot)", k, r, 6);

    // quaternions and poses
    mjtNum q1[4], q2[4], v[3], p1[3], p2[3];
    unit_quat(q1); unit_quat(q2); fill(v, 3); fill(p1, 3); fill(p2, 3); s = rnd() * 2;
    mju_rotVecQuat(r, v, q1); out("mju_rotVecQuat", k, r, 3);
    mju_negQuat(r, q1); out("mju_negQuat", k, r, 4);
    mju_mulQuat(r, q1, q2); out("mju_mulQuat", k, r, 4);
    mju_mulQuatAxis(r, q1, v); out("mju_mulQuatAxis", k, r, 4);
    mju_copy3(r2, v); mju_normalize3(r2);
    mju_axisAngle2Quat(r, r2, s); out("mju_axisAngle2Quat", k, r, 4);
    mju_quat2Vel(r, q1, 0.01 + fabs(s)); out("mju_quat2Vel", k, r, 3);
    mju_subQuat(r, q1, q2); out("mju_subQuat", k, r, 3);
    mju_quat2Mat(r, q1); out("mju_quat2Mat", k, r, 9);
    rot_mat(c); mju_mat2Quat(r, c); out("mju_mat2Quat", k, r, 4);
    mju_derivQuat(r, q1, v); out("mju_derivQuat", k, r, 4);
    mju_copy4(r, q1); mju_quatIntegrate(r, v, s); out("mju_quatIntegrate", k, r, 4);
    mju_quatZ2Vec(r, v); out("mju_quatZ2Vec", k, r, 4);
    mju_mulPose(r, r + 3, p1, q1, p2, q2); out("mju_mulPose", k, r, 7);
    mju_negPose(r, r + 3, p1, q1); out("mju_negPose", k, r, 7);
    mju_trnVecPose(r, p1, q1, v); out("mju_trnVecPose", k, r, 3);
    fill(r, 4); r[4] = mju_normalize4(r); out("mju_normalize4", k, r, 5);

    // decompositions
    spd(a, n); fill(b, n);
    mju_copy(c, a, n * n); r[0] = mju_cholFactor(c, n, 1e-10); out("mju_cholFactor", k, r, 1);
    out("mju_cholFactor.L", k, c, n * n);
    mju_cholSolve(r, c, b, n); out("mju_cholSolve", k, r, n);
    for (int i = 0; i < n; i++) d[i] = 0.3 * b[i];
    r[0] = mju_cholUpdate(c, d, n, 1); out("mju_cholUpdate", k, r, 1);
    out("mju_cholUpdate.L", k, c, n * n);
    spd(a, 3);
    mjtNum eigval[3], eigvec[9], quat[4];
    r[0] = mju_eig3(eigval, eigvec, quat, a); out("mju_eig3", k, r, 1);
    out("mju_eig3.val", k, eigval, 3); out("mju_eig3.vec", k, eigvec, 9); out("mju_eig3.quat", k, quat, 4);

    // actuator and misc scalar functions
    mjtNum lr[2] = {0.5, 1.5}, prm[9] = {0.75, 1.05, 1.4, 0.4, 1.4, 1.2, 0, 1.3, 1.2};
    mjtNum len = 0.6 + 0.5 * (rnd() + 1), vel = rnd() * 3, dynprm[2] = {0.01, 0.04};
    out1("mju_muscleGain", k, mju_muscleGain(len, vel, lr, 20, prm));
    out1("mju_muscleBias", k, mju_muscleBias(len, lr, 20, prm));
    out1("mju_muscleDynamics", k, mju_muscleDynamics(rnd(), (rnd() + 1) / 2, dynprm));
    mjtNum force[6], mu[5], pyr[10];
    fill(force, 6); force[0] = fabs(force[0]) + 0.1;
    for (int i = 0; i < 5; i++) mu[i] = 0.5 + 0.4 * rnd();
    int dim = 3 + (k % 2) * 3;
    mju_encodePyramid(pyr, force, mu, dim); out("mju_encodePyramid", k, pyr, 2 * (dim - 1));
    mju_decodePyramid(r, pyr, mu, dim); out("mju_decodePyramid", k, r, dim);
    out1("mju_springDamper", k, mju_springDamper(rnd(), rnd(), 10 + 5 * rnd(), 1 + rnd(), 0.01));
    s = rnd() * 5;
    out1("mju_min", k, mju_min(s, 0.3));
    out1("mju_max", k, mju_max(s, 0.3));
    out1("mju_clip", k, mju_clip(s, -1, 2));
    out1("mju_sign", k, mju_sign(s));
    out1("mju_round", k, mju_round(s));
    out1("mju_isBad", k, mju_isBad(s * 1e10));
    out1("mju_sigmoid", k, mju_sigmoid(s / 3));
    out1("mju_Halton", k, mju_Halton(k + 1, 2 + k % 5));
    fill(a, 9); mju_insertionSort(a, 9); out("mju_insertionSort", k, a, 9);
  }
  for (int t = 0; t <= mjOBJ_KEY; t++) printf("mju_type2Str#%d %s\n", t, mju_type2Str(t));
  for (int w = 0; w < mjNWARNING; w++) printf("mju_warningText#%d %s\n", w, mju_warningText(w, 7));
  return 0;
}
