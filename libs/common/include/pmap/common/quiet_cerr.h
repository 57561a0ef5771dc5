// Silences std::cerr for a scope: libraries that report on it (OctoMap's
// reader: "Reading binary octree type OcTree") must not write on a program's
// stderr, which is for its own one-line errors and warnings.
#pragma once

#include <iostream>

namespace pmap {

class QuietCerr {
 public:
  QuietCerr() : old_(std::cerr.rdbuf(nullptr)) {}
  ~QuietCerr() {
    std::cerr.rdbuf(old_);
    std::cerr.clear();  // a stream without a buffer sets badbit when written to
  }
  QuietCerr(const QuietCerr&) = delete;
  QuietCerr& operator=(const QuietCerr&) = delete;

 private:
  std::streambuf* old_;
};

}  // namespace pmap
