// map-eval: see `map-eval --help` and doc/evaluation.md.
#include "pmap/eval/map_eval_app.h"

int main(int argc, char** argv) {
  return pmap::eval::mapEvalMain(argc, argv);
}
