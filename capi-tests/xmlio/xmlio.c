/* XML I/O driver for tests/xml_io.rs:
 *   xmlio mjb IN OUT.mjb     load IN (MJCF or URDF), save the model as MJB
 *   xmlio save IN OUT.xml    load IN, mj_saveLastXML to OUT
 *   xmlio changed IN OUT.xml changes the model's timestep, then mj_saveLastXML to OUT
 *   xmlio schema OUT html pad  mj_printSchema to OUT
 * Exit 0 on success; errors on stdout. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <mujoco/mujoco.h>

int main(int argc, char** argv) {
  char err[1000] = "";
  if (argc == 5 && !strcmp(argv[1], "schema")) {
    int n = mj_printSchema(argv[2], NULL, 0, atoi(argv[3]), atoi(argv[4]));
    printf("%d\n", n);
    return 0;
  }
  if (argc != 4) return 2;
  mjModel* m = mj_loadXML(argv[2], NULL, err, sizeof(err));
  if (!m) {
    printf("load error: %s\n", err);
    return 1;
  }
  int ok = 1;
  if (!strcmp(argv[1], "changed")) {
    m->opt.timestep *= 2;
    ok = mj_saveLastXML(argv[3], m, err, sizeof(err));
    printf("saved %d: %s\n", ok, err);
  } else if (!strcmp(argv[1], "mjb")) {
    mj_saveModel(m, argv[3], NULL, 0);
  } else {
    ok = mj_saveLastXML(argv[3], m, err, sizeof(err));
    if (!ok) printf("save error: %s\n", err);
    mj_freeLastXML();
    if (mj_saveLastXML(argv[3], m, err, sizeof(err)) || strcmp(err, "No XML model loaded")) {
      printf("freeLastXML did not forget the model: %s\n", err);
      ok = 0;
    }
  }
  mj_deleteModel(m);
  return ok ? 0 : 1;
}
