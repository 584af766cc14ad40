// The workload rujoco's build profile is recorded on (cargo xtask pgo): for each model file
// given, what programs do with a model, in proportions like theirs. Loads it (XML, then through
// an MJB round trip), steps it with driven controls (full physics, then with constraints and
// contacts disabled), and calls mj_forward, mj_inverse, site Jacobians, object velocities and
// accelerations, contact forces, mj_mulM, mj_integratePos, a controller's quaternion and
// vector math and other calls between steps, rays from each camera and mjv_updateScene. Prints nothing; a model the library rejects is skipped. One process per file:
// the instrumented library writes its counts when the process exits.
//   pgo_train STEPS FILE
#define _POSIX_C_SOURCE 200809L  // clock_gettime, getpid under -std=c11
#include <math.h>
#include <mujoco/mujoco.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static void quiet(const char* msg) { (void)msg; }

static double seconds(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// STEPS driven steps, then more while they have taken less than 20 ms (up to 40 times as many):
// a small model's per-call path weighs in the profile as it does in a program's time
static void drive(mjModel* m, mjData* d, int steps, int disable) {
  int saved = m->opt.disableflags;
  m->opt.disableflags |= disable;
  if (m->nkey) {
    mj_resetDataKeyframe(m, d, 0);
  } else {
    mj_resetData(m, d);
  }
  double start = seconds();
  for (int i = 0; i < 40 * steps; i++) {
    if (i >= steps && i % steps == 0 && seconds() - start > 0.02) break;
    for (int u = 0; u < m->nu; u++) d->ctrl[u] = 0.5 * sin(0.01 * i + u);
    mj_step(m, d);
  }
  m->opt.disableflags = saved;
}

// A controller's own math on the poses (the mju_ functions): quaternions, rotations, small
// vectors and matrices.
static void math(const mjModel* m, const mjData* d) {
  mjtNum q[4], r[9], v[3], w[3], mat[9], sum = 0;
  for (int b = 0; b < m->nbody; b++) {
    const mjtNum *xq = d->xquat + 4 * b, *xp = d->xpos + 3 * b, *xm = d->xmat + 9 * b;
    mju_mulQuat(q, xq, xq);
    mju_negQuat(r, q);
    mju_subQuat(v, q, xq);
    mju_quat2Mat(mat, q);
    mju_mat2Quat(q, mat);
    mju_rotVecQuat(v, xp, q);
    mju_rotVecMat(w, v, xm);
    mju_rotVecMatT(v, w, xm);
    mju_mulMatVec(w, xm, v, 3, 3);
    mju_mulMatTVec(v, xm, w, 3, 3);
    mju_mulMatMat(r, xm, mat, 3, 3, 3);
    mju_cross(w, v, xp);
    mju_sub3(v, w, xp);
    mju_add3(w, v, xp);
    mju_scl3(v, w, 0.5);
    sum += mju_dot3(v, w) + mju_norm3(v) + mju_dist3(v, xp) + mju_normalize3(w);
    sum += mju_dot(xm, mat, 9) + mju_norm(xm, 9);
    mju_copy4(q, xq);
    mju_quatIntegrate(q, v, 0.001);
    sum += mju_normalize4(q);
    mju_axisAngle2Quat(q, w, 0.1);
    mju_quat2Vel(v, q, 0.01);
    mju_mulQuatAxis(q, xq, w);
    mju_mulPose(v, q, xp, xq, w, q);
  }
  (void)sum;
}

// The rest of what controllers, planners and training loops call between steps: names, frames,
// the mass matrix and its solves, Jacobian products, applied forces, position differences,
// energies, copies of the data and finite-difference derivatives.
static void api(const mjModel* m, mjData* d) {
  int nv = m->nv ? m->nv : 1;
  mjtNum* a = calloc(nv * nv, sizeof(mjtNum));
  mjtNum* b = calloc(nv * 3, sizeof(mjtNum));
  mjtNum *x = calloc(nv, sizeof(mjtNum)), *y = calloc(nv, sizeof(mjtNum));
  mjtNum pos[3], mat[9], f[3] = {0.1, 0.2, 0.3};
  mjtNum sum = mj_getTotalmass(m);
  for (int t = mjOBJ_BODY; t <= mjOBJ_ACTUATOR; t++) {
    for (int i = 0; i < 8; i++) {
      const char* name = mj_id2name(m, t, i);
      if (name) sum += mj_name2id(m, t, name);
    }
  }
  for (int i = 1; i < m->nbody; i++) {
    mj_local2Global(d, pos, mat, f, d->xquat + 4 * i, i, 0);
    mj_applyFT(m, d, f, f, d->xipos + 3 * i, i, d->qfrc_applied);
    mj_jacBody(m, d, b, NULL, i);
    mj_jac(m, d, b, NULL, d->xipos + 3 * i, i);
  }
  for (int g = 0; g < m->ngeom && g < 20; g++) mj_jacGeom(m, d, b, NULL, g);
  mj_fullM(m, a, d->qM);
  for (int k = 0; k < 5; k++) {
    mj_solveM(m, d, x, d->qfrc_bias, 1);
    mj_solveM2(m, d, y, d->qfrc_bias, 1);
    mj_differentiatePos(m, x, 0.01, d->qpos, d->qpos);
    mj_subtreeVel(m, d);
    mj_rnePostConstraint(m, d);
    mj_rne(m, d, 1, y);
    mj_energyPos(m, d);
    mj_energyVel(m, d);
  }
  if (d->nefc) {
    mjtNum* r = calloc(d->nefc, sizeof(mjtNum));
    mj_mulJacVec(m, d, r, d->qvel);
    mj_mulJacTVec(m, d, x, r);
    free(r);
  }
  mjData* copy = mj_copyData(NULL, m, d);
  mj_copyData(copy, m, d);
  mj_deleteData(copy);
  if (m->nv <= 60) {
    mjtNum* A = calloc((2 * m->nv + m->na) * (2 * m->nv + m->na), sizeof(mjtNum));
    mjd_transitionFD(m, d, 1e-6, 1, A, NULL, NULL, NULL);
    free(A);
  }
  mju_zero(d->qfrc_applied, m->nv);
  (void)sum;
  free(a);
  free(b);
  free(x);
  free(y);
}

static void queries(const mjModel* m, mjData* d, mjvScene* scn) {
  math(m, d);
  api(m, d);
  mj_forward(m, d);
  mj_inverse(m, d);
  mjtNum* jacp = malloc(sizeof(mjtNum) * 3 * (m->nv ? m->nv : 1));
  mjtNum* jacr = malloc(sizeof(mjtNum) * 3 * (m->nv ? m->nv : 1));
  for (int s = 0; s < m->nsite; s++) mj_jacSite(m, d, jacp, jacr, s);
  for (int b = 0; b < m->nbody; b++) mj_jacBodyCom(m, d, jacp, NULL, b);
  // a controller's or reward's small queries
  mjtNum v6[6];
  for (int b = 0; b < m->nbody; b++) {
    mj_objectVelocity(m, d, mjOBJ_BODY, b, v6, 0);
    mj_objectAcceleration(m, d, mjOBJ_XBODY, b, v6, 1);
  }
  for (int c = 0; c < d->ncon; c++) mj_contactForce(m, d, c, v6);
  for (int k = 0; k < 10; k++) mj_mulM(m, d, jacp, d->qvel);
  mjtNum* q = malloc(sizeof(mjtNum) * (m->nq ? m->nq : 1));
  memcpy(q, d->qpos, sizeof(mjtNum) * m->nq);
  for (int k = 0; k < 10; k++) mj_integratePos(m, q, d->qvel, 0.001);
  free(q);
  free(jacp);
  free(jacr);
  for (int c = 0; c < m->ncam; c++) {
    mjtNum dir[3] = {-d->cam_xmat[9 * c + 2], -d->cam_xmat[9 * c + 5], -d->cam_xmat[9 * c + 8]};
    int geom = -1;
    mj_ray(m, d, d->cam_xpos + 3 * c, dir, NULL, 1, -1, &geom);
  }
  mjvOption opt;
  mjvCamera cam;
  mjvPerturb pert;
  mjv_defaultOption(&opt);
  mjv_defaultCamera(&cam);
  mjv_defaultPerturb(&pert);
  mjv_updateScene(m, d, &opt, &pert, &cam, mjCAT_ALL, scn);
}

static void train(const char* file, int steps) {
  char err[1000];
  mjModel* m = mj_loadXML(file, NULL, err, sizeof err);
  if (!m) return;
  int size = mj_sizeModel(m);
  void* buf = malloc(size);
  mj_saveModel(m, NULL, buf, size);
  mj_deleteModel(m);
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "model.mjb", size);
  memcpy(vfs.filedata[0], buf, size);
  free(buf);
  m = mj_loadModel("model.mjb", &vfs);
  mj_deleteVFS(&vfs);
  if (!m) return;
  // the file path of mj_loadModel, and mj_copyModel
  char path[64];
  snprintf(path, sizeof path, "/tmp/rujoco-pgo-%d.mjb", (int)getpid());
  mj_saveModel(m, path, NULL, 0);
  mj_deleteModel(mj_loadModel(path, NULL));
  remove(path);
  mj_deleteModel(mj_copyModel(NULL, m));
  mjData* d = mj_makeData(m);
  mjvScene scn;
  mjv_defaultScene(&scn);
  mjv_makeScene(m, &scn, 2000);
  drive(m, d, steps, 0);
  queries(m, d, &scn);
  drive(m, d, steps / 2, mjDSBL_CONSTRAINT | mjDSBL_CONTACT);
  queries(m, d, &scn);
  mjv_freeScene(&scn);
  mj_deleteData(d);
  mj_deleteModel(m);
}

int main(int argc, char** argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: pgo_train STEPS FILE\n");
    return 2;
  }
  mju_user_warning = quiet;
  train(argv[2], atoi(argv[1]));
  return 0;
}
