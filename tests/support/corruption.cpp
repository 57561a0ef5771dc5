#include "corruption.h"

#include <grp.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

namespace pmap::testing {
namespace fs = std::filesystem;

Bytes readFileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void writeFileBytes(const fs::path& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

void flipBytes(Bytes& bytes, std::uint32_t seed, int count) {
  if (bytes.empty()) {
    return;
  }
  std::uint64_t state = 0x9E3779B97F4A7C15ull ^ seed;
  auto next = [&state] {  // splitmix64
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  };
  for (int i = 0; i < count; ++i) {
    const std::size_t at = next() % bytes.size();
    const auto mask = static_cast<unsigned char>(1 + next() % 255);
    bytes[at] = static_cast<char>(static_cast<unsigned char>(bytes[at]) ^ mask);
  }
}

std::vector<std::size_t> findUint32(const Bytes& bytes, std::uint32_t value) {
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i + 4 <= bytes.size(); ++i) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + i, 4);
    if (v == value) {
      at.push_back(i);
    }
  }
  return at;
}

std::vector<std::size_t> findText(const Bytes& bytes, const std::string& text) {
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i + text.size() <= bytes.size(); ++i) {
    if (std::memcmp(bytes.data() + i, text.data(), text.size()) == 0) {
      at.push_back(i);
    }
  }
  return at;
}

void putUint32(Bytes& bytes, std::size_t offset, std::uint32_t value) {
  std::memcpy(bytes.data() + offset, &value, 4);
}

double peakRssMiB() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) {
      return std::stod(line.substr(6)) / 1024.0;  // "VmHWM:   12345 kB"
    }
  }
  return -1.0;
}

bool runningAsRoot() {
  return ::geteuid() == 0;
}

int runUnprivileged(const std::function<int()>& check) {
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    return -1;
  }
  if (pid == 0) {
    if (runningAsRoot() &&
        (::setgroups(0, nullptr) != 0 || ::setgid(65534) != 0 || ::setuid(65534) != 0)) {
      ::_exit(125);
    }
    const int status = check();
    std::fflush(nullptr);
    ::_exit(status);
  }
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid || !WIFEXITED(status)) {
    return -1;
  }
  return WEXITSTATUS(status);
}

}  // namespace pmap::testing
