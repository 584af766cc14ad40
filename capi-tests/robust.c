// Robustness probe (tests/robust.rs): API calls with invalid ids, NULL pointers and negative
// sizes, against our library. Each call must return (after reporting through mju_error or
// not at all), never crash. The error handler returns, as a user's may; one line per call.
#include <mujoco/mujoco.h>
#include <stdio.h>
#include <string.h>

static int errors = 0;
static void on_error(const char* msg) {
  errors++;
  printf("    mju_error: %.100s\n", msg);
}
static void quiet(const char* msg) { (void)msg; }

#define CALL(expr)                      \
  do {                                  \
    printf("%s\n", #expr);              \
    fflush(stdout);                     \
    expr;                               \
  } while (0)

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  mju_user_error = on_error;
  mju_user_warning = quiet;
  char err[1000] = "";
  mjModel* m = mj_loadXML(argv[1], NULL, err, sizeof err);
  if (!m) {
    printf("load failed: %s\n", err);
    return 1;
  }
  mjData* d = mj_makeData(m);
  mj_forward(m, d);
  mjtNum jp[3 * 1000], jr[3 * 1000], res[6], pt[3] = {0, 0, 0}, ax[3] = {0, 0, 1};
  mjtNum v[1000] = {0};
  int big = 1 << 20;
  CALL(mj_jac(m, d, jp, jr, pt, -1));
  CALL(mj_jac(m, d, jp, jr, pt, m->nbody));
  CALL(mj_jacBody(m, d, jp, jr, -1));
  CALL(mj_jacBody(m, d, jp, jr, big));
  CALL(mj_jacBodyCom(m, d, jp, jr, -7));
  CALL(mj_jacBodyCom(m, d, jp, jr, m->nbody));
  CALL(mj_jacGeom(m, d, jp, jr, -1));
  CALL(mj_jacGeom(m, d, jp, jr, m->ngeom));
  CALL(mj_jacSite(m, d, jp, jr, -1));
  CALL(mj_jacSite(m, d, jp, jr, m->nsite));
  CALL(mj_jacSubtreeCom(m, d, jp, -1));
  CALL(mj_jacSubtreeCom(m, d, jp, m->nbody));
  CALL(mj_jacPointAxis(m, d, jp, jr, pt, ax, -1));
  CALL(mj_jacPointAxis(m, d, jp, jr, pt, ax, m->nbody));
  CALL(mj_objectVelocity(m, d, 999, 0, res, 0));
  CALL(mj_objectVelocity(m, d, mjOBJ_BODY, -1, res, 0));
  CALL(mj_objectVelocity(m, d, mjOBJ_SITE, big, res, 1));
  CALL(mj_objectVelocity(m, d, mjOBJ_CAMERA, m->ncam, res, 1));
  CALL(mj_objectAcceleration(m, d, -3, 0, res, 0));
  CALL(mj_objectAcceleration(m, d, mjOBJ_GEOM, m->ngeom, res, 0));
  CALL(mj_objectAcceleration(m, d, mjOBJ_XBODY, -1, res, 1));
  CALL(mj_contactForce(m, d, -1, res));
  CALL(mj_contactForce(m, d, big, res));
  CALL(mj_id2name(m, 999, 0));
  CALL(mj_id2name(m, -1, 0));
  CALL(mj_id2name(m, mjOBJ_BODY, -1));
  CALL(mj_id2name(m, mjOBJ_BODY, big));
  CALL(mj_name2id(m, 999, "x"));
  CALL(mj_name2id(m, mjOBJ_BODY, NULL));
  CALL(mj_resetDataKeyframe(m, d, -1));
  CALL(mj_resetDataKeyframe(m, d, m->nkey));
  CALL(mj_applyFT(m, d, pt, pt, pt, -1, v));
  CALL(mj_applyFT(m, d, pt, pt, pt, m->nbody, v));
  CALL(mj_stackAlloc(d, -1));
  CALL(mj_stackAlloc(d, big * 1000));
  CALL(mju_zero(v, -1));
  CALL(mju_copy(v, jp, -5));
  CALL(mju_dot(v, v, -1));
  CALL(mju_rayGeom(pt, pt, pt, pt, ax, 99));
  CALL(mju_rayGeom(pt, pt, pt, pt, ax, -1));
  CALL(mj_ray(m, d, pt, ax, NULL, 1, -5, v == NULL ? NULL : (int[1]){0}));
  CALL(mj_step(NULL, d));
  CALL(mj_step(m, NULL));
  CALL(mj_forward(NULL, NULL));
  CALL(mj_inverse(m, NULL));
  CALL(mj_kinematics(NULL, d));
  CALL(mj_copyData(NULL, m, d));
  CALL(mj_resetData(NULL, d));
  CALL(mj_deleteData(NULL));
  CALL(mj_deleteModel(NULL));
  CALL(mj_printModel(NULL, "/dev/null"));
  CALL(mj_saveModel(m, NULL, NULL, 0));
  CALL(mj_sizeModel(NULL));
  CALL(mj_energyPos(m, NULL));
  CALL(mj_sensorPos(NULL, d));
  CALL(mj_mulJacVec(m, d, v, NULL));
  CALL(mj_fullM(NULL, v, v));
  CALL(mj_integratePos(m, NULL, v, 0.01));
  mj_deleteData(d);
  mj_deleteModel(m);
  printf("done, %d errors reported\n", errors);
  return 0;
}
