#include "cli/atomic_file.hpp"

#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>

#include <unistd.h>

namespace adcs::sim::cli {
namespace fs = std::filesystem;
namespace ADCS_UNITY_ID {

// Paths the signal handler removes: files first (unlink), then directories (rmdir, newest
// first). Fixed storage so that the handler only touches async-signal-safe state.
constexpr int kSlots = 32;
constexpr std::size_t kPathMax = 4096;
char g_paths[kSlots][kPathMax];
volatile std::sig_atomic_t g_used[kSlots];  // 0 free, 1 file, 2 directory

int register_path(const std::string& p, int kind) {
  if (p.size() >= kPathMax) return -1;
  for (int i = 0; i < kSlots; ++i) {
    if (g_used[i] == 0) {
      std::memcpy(g_paths[i], p.c_str(), p.size() + 1);
      g_used[i] = kind;
      return i;
    }
  }
  return -1;  // not registered: only the signal cleanup is lost
}

void unregister(int& slot) noexcept {
  if (slot >= 0) g_used[slot] = 0;
  slot = -1;
}

extern "C" void cleanup_on_signal(int sig) {
  for (int i = 0; i < kSlots; ++i)
    if (g_used[i] == 1) ::unlink(g_paths[i]);
  for (int i = kSlots - 1; i >= 0; --i)
    if (g_used[i] == 2) ::rmdir(g_paths[i]);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

void install_cleanup_signal_handlers() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, cleanup_on_signal);
}

OutputDir::OutputDir(const fs::path& dir) : dir_(dir) {
  if (dir_.empty()) throw IoError("empty output directory");
  std::error_code ec;
  // Find the missing ancestors so that only what we create is removed again.
  std::vector<fs::path> missing;
  for (fs::path p = fs::absolute(dir_, ec).lexically_normal(); !p.empty(); p = p.parent_path()) {
    if (p.has_relative_path() && !p.has_filename()) p = p.parent_path();  // trailing '/'
    if (fs::exists(p, ec)) break;
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!fs::create_directory(*it, ec) && ec) {
      // Undo what we made before failing.
      for (auto jt = created_.rbegin(); jt != created_.rend(); ++jt) fs::remove(*jt, ec);
      throw IoError("cannot create directory '" + it->string() + "': " + ec.message());
    }
    created_.push_back(*it);
    slots_.push_back(register_path(it->string(), 2));
  }
  if (!fs::is_directory(dir_, ec))
    throw IoError("output path '" + dir_.string() + "' is not a directory");
}

void OutputDir::keep() noexcept {
  keep_ = true;
  for (int& s : slots_) unregister(s);
}

OutputDir::~OutputDir() {
  for (int& s : slots_) unregister(s);
  if (keep_) return;
  std::error_code ec;
  for (auto it = created_.rbegin(); it != created_.rend(); ++it)
    if (fs::is_empty(*it, ec)) fs::remove(*it, ec);
}

TempFile::TempFile(const fs::path& dir, const std::string& final_name)
    : temp_((dir / ("." + final_name + ".tmp-" + std::to_string(::getpid()))).string()),
      final_((dir / final_name).string()) {
  slot_ = register_path(temp_, 1);
}

TempFile::~TempFile() { discard(); }

bool TempFile::temp_exists() const {
  std::error_code ec;
  return fs::is_regular_file(temp_, ec);
}

void TempFile::write(const std::string& content) {
  std::ofstream f(temp_, std::ios::binary | std::ios::trunc);
  if (!f) throw IoError("cannot open '" + temp_ + "' for writing");
  f << content;
  f.close();
  if (!f) throw IoError("cannot write '" + temp_ + "'");
}

void TempFile::commit() {
  std::error_code ec;
  fs::rename(temp_, final_, ec);
  if (ec) {
    discard();
    throw IoError("cannot rename '" + temp_ + "' to '" + final_ + "': " + ec.message());
  }
  committed_ = true;
  unregister(slot_);
}

void TempFile::uncommit() noexcept {
  if (!committed_) return;
  std::error_code ec;
  fs::remove(final_, ec);
  committed_ = false;
}

void TempFile::discard() noexcept {
  if (!committed_) {
    std::error_code ec;
    fs::remove(temp_, ec);
  }
  unregister(slot_);
}

}  // namespace adcs::sim::cli
