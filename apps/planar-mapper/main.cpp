// planar-mapper: see `planar-mapper --help` and doc/usage.md.
#include "pmap/mapper/planar_mapper_app.h"

int main(int argc, char** argv) {
  return pmap::mapper::planarMapperMain(argc, argv);
}
