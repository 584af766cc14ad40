// Peak resident memory of loading a model: mj_loadXML, mj_deleteModel, then the process's
// high-water mark (VmHWM, kB) and the resident size after the load (VmRSS) on stdout.
#include <stdio.h>
#include <string.h>
#include <mujoco/mujoco.h>

static long status_kb(const char* key) {
  FILE* f = fopen("/proc/self/status", "r");
  char line[256];
  long v = -1;
  while (f && fgets(line, sizeof line, f)) {
    if (!strncmp(line, key, strlen(key))) sscanf(line + strlen(key), "%ld", &v);
  }
  if (f) fclose(f);
  return v;
}

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  char err[1000] = "";
  mjModel* m = mj_loadXML(argv[1], NULL, err, sizeof err);
  if (!m) {
    printf("error: %s\n", err);
    return 1;
  }
  long rss = status_kb("VmRSS:");
  mj_deleteModel(m);
  printf("peak %ld rss %ld\n", status_kb("VmHWM:"), rss);
  return 0;
}
