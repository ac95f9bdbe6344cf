#pragma once
// All-or-nothing output for adcs-sim: files are written under a temporary name in their final
// directory (".NAME.tmp-<pid>") and renamed into place only once everything succeeded; on any
// failure, destruction, or SIGINT/SIGTERM/SIGHUP the temporaries (and directories adcs-sim
// created for them, if still empty) are removed.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace adcs::sim::cli {

//! Failure to create, write or rename an output file (adcs-sim exits 1).
struct IoError : std::runtime_error {
  using runtime_error::runtime_error;
};

//! Installs the signal handlers that remove registered temporaries (idempotent).
void install_cleanup_signal_handlers();

//! Creates `dir` (and missing parents). Directories it created are removed again on
//! destruction if still empty, unless keep() was called.
class OutputDir {
 public:
  explicit OutputDir(const std::filesystem::path& dir);
  ~OutputDir();
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;
  const std::filesystem::path& path() const noexcept { return dir_; }
  void keep() noexcept;

 private:
  std::filesystem::path dir_;
  std::vector<std::filesystem::path> created_;  // outermost first
  std::vector<int> slots_;
  bool keep_ = false;
};

//! One output file: `dir/.final_name.tmp-<pid>` until commit() renames it to `dir/final_name`.
class TempFile {
 public:
  TempFile(const std::filesystem::path& dir, const std::string& final_name);
  ~TempFile();  // removes the temporary unless committed
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  const std::string& temp_path() const noexcept { return temp_; }
  const std::string& final_path() const noexcept { return final_; }
  bool temp_exists() const;
  //! Writes `content` as the whole temporary file (throws IoError).
  void write(const std::string& content);
  //! Renames the temporary into place (throws IoError; the temporary is then removed).
  void commit();
  //! Removes the committed file again (best effort; used when a later commit fails).
  void uncommit() noexcept;
  //! Removes the temporary (idempotent, noexcept).
  void discard() noexcept;

 private:
  std::string temp_, final_;
  int slot_ = -1;
  bool committed_ = false;
};

}  // namespace adcs::sim::cli
