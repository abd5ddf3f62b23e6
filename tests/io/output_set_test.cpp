// OutputSet and AtomicOutput: outputs checked before the work, no collision with inputs or each
// other, every target replaced together at commit or none, short temporaries (so 255-byte names
// work), and temporaries removed on failure and on SIGINT/SIGTERM.
#include "io/output_set.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>

#include "base/error.hpp"
#include "io/atomic_output.hpp"
#include "temporary_files.hpp"

namespace hocav {
namespace {

namespace fs = std::filesystem;

class OutputSetTest : public ::testing::Test {
 protected:
  void SetUp() override { folder_ = testing_support::temporary_folder(); }
  void TearDown() override { fs::remove_all(folder_); }

  std::string path(const std::string& name) const { return (folder_ / name).string(); }
  void write(const std::string& name, const std::string& text) const { std::ofstream(path(name)) << text; }
  std::string read(const std::string& name) const {
    std::ifstream in(path(name));
    return {std::istreambuf_iterator<char>(in), {}};
  }
  std::set<std::string> files() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder_)) names.insert(entry.path().filename().string());
    return names;
  }
  static void write_through(const std::string& target, const std::string& text) {
    AtomicOutput out(target);
    out.stream() << text;
    out.commit();
  }

  fs::path folder_;
};

TEST_F(OutputSetTest, ReplacesEveryTargetOnlyAtCommit) {
  write("a.txt", "old a");
  {
    OutputSet outputs;
    outputs.add_output(path("a.txt"), "-o");
    outputs.add_output(path("b.txt"), "--report");
    write_through(path("a.txt"), "new a");
    write_through(path("b.txt"), "new b");
    EXPECT_EQ(read("a.txt"), "old a");  // written, not yet in place
    EXPECT_FALSE(fs::exists(path("b.txt")));
    outputs.commit();
  }
  EXPECT_EQ(read("a.txt"), "new a");
  EXPECT_EQ(read("b.txt"), "new b");
  EXPECT_EQ(files(), (std::set<std::string>{"a.txt", "b.txt"}));
}

TEST_F(OutputSetTest, AFailureBeforeCommitReplacesNothingAndLeavesNoTemporary) {
  write("a.txt", "old a");
  try {
    OutputSet outputs;
    outputs.add_output(path("a.txt"), "-o");
    outputs.add_output(path("b.txt"), "--report");
    write_through(path("a.txt"), "new a");
    throw Error("the second output failed");
  } catch (const Error&) {
  }
  EXPECT_EQ(read("a.txt"), "old a");
  EXPECT_EQ(files(), std::set<std::string>{"a.txt"});
}

TEST_F(OutputSetTest, RefusesBadOutputsBeforeAnyWork) {
  OutputSet outputs;
  EXPECT_THROW(outputs.add_output(path("missing/x.txt"), "-o"), Error);
  EXPECT_THROW(outputs.add_output(folder_.string(), "-o"), Error);  // a folder
  EXPECT_THROW(outputs.add_output("", "-o"), Error);
  EXPECT_THROW(outputs.add_output("/dev/null", "-o"), Error);  // not a regular file
  EXPECT_THROW(AtomicOutput(path("undeclared.txt")), Error);   // a command must declare what it writes
}

TEST_F(OutputSetTest, RefusesAnOutputNamingAnInputOrAnotherOutputInAnyForm) {
  write("in.mesh", "input");
  fs::create_symlink(path("in.mesh"), path("link.mesh"));
  fs::create_hard_link(path("in.mesh"), path("hard.mesh"));
  const std::string dotted = (folder_ / "." / "in.mesh").string();
  for (const std::string& alias : {path("in.mesh"), dotted, path("link.mesh"), path("hard.mesh")}) {
    OutputSet outputs;
    outputs.add_input(path("in.mesh"), "the input mesh");
    EXPECT_THROW(outputs.add_output(alias, "-o"), Error) << alias;
  }
  OutputSet outputs;
  outputs.add_output(path("out.mesh"), "-o");  // does not exist yet: compared by resolved path
  try {
    fs::create_directory(folder_ / "sub");
    outputs.add_output((folder_ / "sub" / ".." / "out.mesh").string(), "--vtu");
    ADD_FAILURE() << "a second output on the same file was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("--vtu names the same file as -o"), std::string::npos) << error.what();
  }
  outputs.add_input(path("in.mesh"), "the input mesh");  // inputs may repeat
  outputs.add_input(path("in.mesh"), "--metric");
}

TEST_F(OutputSetTest, WritesTargetsWhoseNameHasTheLongestLegalLength) {
  const std::string name = std::string(250, 'a') + ".mesh";  // 255 bytes
  OutputSet outputs;
  outputs.add_output(path(name), "-o");
  write_through(path(name), "long");
  outputs.commit();
  EXPECT_EQ(read(name), "long");
}

TEST_F(OutputSetTest, WithoutASetAtomicOutputRenamesAtOnce) {
  write_through(path("alone.txt"), "alone");
  EXPECT_EQ(files(), std::set<std::string>{"alone.txt"});
}

// A child writes an output and is then killed by `signal` before the commit: the signal kills it
// as before, and its temporary is gone.
void expect_signal_removes_temporaries(const std::string& target, int signal_number) {
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    OutputSet outputs;
    outputs.add_output(target, "-o");
    AtomicOutput out(target);
    out.stream() << "partial";
    out.stream().flush();
    std::raise(signal_number);
    _exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << "status " << status;
}

TEST_F(OutputSetTest, SigintAndSigtermRemoveTheTemporaries) {
  for (int signal_number : {SIGINT, SIGTERM}) {
    expect_signal_removes_temporaries(path("out.mesh"), signal_number);
    EXPECT_TRUE(files().empty()) << "signal " << signal_number << " left " << *files().begin();
  }
}

}  // namespace
}  // namespace hocav
