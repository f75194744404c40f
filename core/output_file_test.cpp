#include "core/output_file.hpp"

#include <doctest/doctest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using ncsim::core::OutputFile;

namespace {

// A fresh scratch folder, removed at the end of the test.
struct Scratch {
  fs::path dir;
  Scratch() {
    std::string t = (fs::temp_directory_path() / "ncsim-output-XXXXXX").string();
    REQUIRE(::mkdtemp(t.data()) != nullptr);
    dir = t;
  }
  ~Scratch() {
    std::error_code ec;
    fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(dir, ec);
  }
};

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t files_in(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir))
    ++n;
  return n;
}

OutputFile opened(const fs::path& target) {
  auto o = OutputFile::open(target);
  REQUIRE_MESSAGE(std::holds_alternative<OutputFile>(o), std::get<std::string>(o));
  return std::move(std::get<OutputFile>(o));
}

std::string refused(const fs::path& target) {
  auto o = OutputFile::open(target);
  REQUIRE(std::holds_alternative<std::string>(o));
  return std::get<std::string>(o);
}

}  // namespace

TEST_CASE("a new file is written to a temporary file in its folder and renamed when committed") {
  Scratch s;
  const fs::path target = s.dir / "out.csv";
  OutputFile o = opened(target);
  CHECK(o.written().parent_path() == s.dir);
  CHECK(o.written().filename().string().rfind("out.csv.", 0) == 0);
  CHECK(o.written().extension() == ".tmp");
  CHECK(o.write("a,b\n"));
  CHECK_FALSE(fs::exists(target));  // nothing at the target before the commit
  std::string why;
  CHECK(o.commit(why));
  CHECK(read(target) == "a,b\n");
  CHECK(files_in(s.dir) == 1);  // no temporary file left
}

TEST_CASE("two writers of the same target never share a temporary file") {
  Scratch s;
  const fs::path target = s.dir / "out.csv";
  OutputFile a = opened(target);
  OutputFile b = opened(target);
  CHECK(a.written() != b.written());
  a.write("first\n");
  b.write("second\n");
  std::string why;
  CHECK(a.commit(why));
  CHECK(b.commit(why));
  CHECK(read(target) == "second\n");  // the last complete file wins, never a mix
  CHECK(files_in(s.dir) == 1);
}

TEST_CASE("discard leaves an existing target untouched and removes the temporary file") {
  Scratch s;
  const fs::path target = s.dir / "keep.csv";
  std::ofstream(target) << "keep me\n";
  {
    OutputFile o = opened(target);
    o.write("half a run");
  }  // the destructor discards
  CHECK(read(target) == "keep me\n");
  CHECK(files_in(s.dir) == 1);
}

TEST_CASE("a replaced file keeps its permissions") {
  Scratch s;
  const fs::path target = s.dir / "mode.csv";
  std::ofstream(target) << "old\n";
  fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  OutputFile o = opened(target);
  o.write("new\n");
  std::string why;
  REQUIRE(o.commit(why));
  CHECK(fs::status(target).permissions() ==
        (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
}

TEST_CASE("a symbolic link is followed: its target is replaced, the link stays") {
  Scratch s;
  fs::create_directory(s.dir / "runs");
  std::ofstream(s.dir / "runs" / "r1.csv") << "old\n";
  fs::create_symlink("runs/r1.csv", s.dir / "latest.csv");
  OutputFile o = opened(s.dir / "latest.csv");
  CHECK(o.written().parent_path() == s.dir / "runs");
  o.write("new\n");
  std::string why;
  REQUIRE(o.commit(why));
  CHECK(fs::is_symlink(s.dir / "latest.csv"));
  CHECK(read(s.dir / "runs" / "r1.csv") == "new\n");
}

TEST_CASE("a character device is written in place, never replaced") {
  OutputFile o = opened("/dev/null");
  CHECK(o.in_place());
  CHECK(o.write("x"));
  std::string why;
  CHECK(o.commit(why));
  struct stat st {};
  REQUIRE(::stat("/dev/null", &st) == 0);
  CHECK(S_ISCHR(st.st_mode));
}

TEST_CASE("a write error on a device is reported by commit with the reason") {
  if (!fs::exists("/dev/full")) return;
  OutputFile o = opened("/dev/full");
  std::string big(1 << 16, 'x');
  o.write(big);
  std::string why;
  CHECK_FALSE(o.commit(why));
  CHECK(why.find("No space left on device") != std::string::npos);
}

TEST_CASE("what an output may not replace is refused with the reason") {
  Scratch s;
  CHECK(refused("") == "an output needs a file name (an empty name was given)");
  CHECK(refused(s.dir) == "cannot write '" + s.dir.string() +
                              "': it is a directory, not a file an output may replace");
  CHECK(refused(s.dir / "no" / "x.csv") == "cannot write '" + (s.dir / "no" / "x.csv").string() +
                                               "': its folder '" + (s.dir / "no").string() +
                                               "' does not exist");
  fs::create_symlink("loop", s.dir / "loop");
  CHECK(refused(s.dir / "loop").find("too many levels of symbolic links") != std::string::npos);
  // A folder no file can be created in: read-only for a user; root writes anywhere but /sys.
  fs::path ro = s.dir / "ro";
  fs::create_directory(ro);
  fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
  if (::geteuid() == 0) ro = "/sys";
  if (fs::is_directory(ro)) {
    CHECK(refused(ro / "x.csv") == "cannot write '" + (ro / "x.csv").string() +
                                       "': cannot create a file in its folder '" + ro.string() +
                                       "': Permission denied");
  }
}
