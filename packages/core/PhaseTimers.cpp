#include "signorini/core/PhaseTimers.hpp"

#include <iostream>
#include <streambuf>

namespace signorini::core {
namespace {
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};
}  // namespace

std::ostream& rootOut(int rank) {
  static NullBuffer nullBuffer;
  static std::ostream nullStream(&nullBuffer);
  return rank == 0 ? std::cout : nullStream;
}

}  // namespace signorini::core
