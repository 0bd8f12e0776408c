// AtomicFile and the writers' failure behaviour: nothing half-written, no stray temporaries,
// an existing file untouched, a clear error naming the path.
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <csignal>
#include <stdexcept>

#include "core/io/atomic_file.hpp"
#include "core/io/packing_writers.hpp"
#include "core/io/temp_file_registry.hpp"
#include "tests/io/io_test_util.hpp"

namespace fp {
namespace {

using test::slurp;
using test::spit;
using test::TempDir;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(AtomicFile, CommitReplacesTargetAndLeavesNoTemporary) {
  TempDir dir;
  const std::string path = dir.file("a.txt");
  spit(path, "old");
  {
    AtomicFile f(path);
    EXPECT_EQ(f.temp_path().rfind(path + ".tmp-", 0), 0u);
    f.stream() << "new";
    EXPECT_EQ(slurp(path), "old");  // not visible before commit
    f.commit();
  }
  EXPECT_EQ(slurp(path), "new");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, DestructorWithoutCommitRemovesTemporaryAndKeepsOldFile) {
  TempDir dir;
  const std::string path = dir.file("a.txt");
  spit(path, "old");
  {
    AtomicFile f(path);
    f.stream() << "half";
  }
  EXPECT_EQ(slurp(path), "old");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, ThrowingBodyLeavesNothingBehind) {
  TempDir dir;
  const std::string fresh = dir.file("fresh.txt");
  const std::string existing = dir.file("existing.txt");
  spit(existing, "keep me");
  auto throwing = [](std::ostream& out) {
    out << "partial";
    throw std::runtime_error("boom");
  };
  EXPECT_EQ(error_of([&] { write_file_atomically(fresh, throwing); }), "boom");
  EXPECT_EQ(error_of([&] { write_file_atomically(existing, throwing); }), "boom");
  EXPECT_EQ(slurp(existing), "keep me");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"existing.txt"});
}

TEST(AtomicFile, MissingFolderIsAnErrorNamingThePath) {
  TempDir dir;
  const std::string path = dir.file("no_such_folder/out.vtu");
  const std::string msg = error_of([&] { AtomicFile f(path); });
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_NE(msg.find("does not exist"), std::string::npos) << msg;
  EXPECT_TRUE(dir.entries().empty());  // the folder was not created

  Packing<3> p;
  p.add(Vec3(0, 0, 0), 1);
  for (const OutputFormat f : {OutputFormat::Vtu, OutputFormat::Yade, OutputFormat::Lammps, OutputFormat::Csv,
                               OutputFormat::Json}) {
    const std::string m = error_of([&] { write_packing<3>(f, path, p, RunRecord{}); });
    EXPECT_NE(m.find(path), std::string::npos) << m;
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, TargetThatIsAFolderIsAnError) {
  TempDir dir;
  std::filesystem::create_directory(dir.path() / "sub");
  const std::string msg = error_of([&] { write_text_file_atomically(dir.file("sub"), "x"); });
  EXPECT_NE(msg.find(dir.file("sub")), std::string::npos) << msg;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"sub"});
}

TEST(AtomicFile, InconsistentPackingFailsWithoutTouchingExistingFile) {
  TempDir dir;
  const std::string path = dir.file("p.csv");
  spit(path, "keep me");
  Packing<3> bad;
  bad.centers.push_back(Vec3(0, 0, 0));  // a centre without a radius
  const std::string msg = error_of([&] { write_packing<3>(OutputFormat::Csv, path, bad, RunRecord{}); });
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_EQ(slurp(path), "keep me");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"p.csv"});
}

// A real write failure in the middle of a file (what a full disk does): the file size limit
// makes write() fail with EFBIG once the temporary passes 64 KiB. Works as root too.
TEST(AtomicFile, WriteFailureMidFileRemovesTemporaryAndKeepsOldFile) {
  TempDir dir;
  Packing<3> big;
  for (int i = 0; i < 20000; ++i) big.add(Vec3(i * 0.1, i * 0.2, i * 0.3), 0.05 + i * 1e-7);
  rlimit old_limit{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);  // get EFBIG instead of a signal
  rlimit small = old_limit;
  small.rlim_cur = 64 * 1024;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  std::vector<std::string> messages;
  for (const OutputFormat f : {OutputFormat::Vtu, OutputFormat::Yade, OutputFormat::Lammps, OutputFormat::Csv,
                               OutputFormat::Json}) {
    const std::string path = dir.file(std::string("p.") + output_format_name(f));
    spit(path, "old content");
    messages.push_back(error_of([&] { write_packing<3>(f, path, big, RunRecord{}); }));
  }
  setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);
  for (const auto& m : messages) EXPECT_NE(m.find("write error"), std::string::npos) << m;
  for (const auto& name : dir.entries()) {
    EXPECT_EQ(name.find(".tmp-"), std::string::npos) << name;
    EXPECT_EQ(slurp(dir.file(name)), "old content") << name;
  }
  EXPECT_EQ(dir.entries().size(), 5u);
}

TEST(AtomicFile, ReadOnlyFolderFailsCleanly) {
  TempDir dir;
  const auto sub = dir.path() / "ro";
  std::filesystem::create_directory(sub);
  std::filesystem::permissions(sub, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  const std::string path = (sub / "a.txt").string();
  if (std::ofstream(path + ".probe")) {  // root ignores permissions
    std::filesystem::permissions(sub, std::filesystem::perms::owner_all);
    GTEST_SKIP() << "running with permissions that ignore a read-only folder (root?)";
  }
  const std::string msg = error_of([&] { write_text_file_atomically(path, "x"); });
  std::filesystem::permissions(sub, std::filesystem::perms::owner_all);
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_TRUE(std::filesystem::is_empty(sub));
}

TEST(AtomicFile, SymbolicLinkIsWrittenThrough) {
  TempDir dir;
  spit(dir.file("real.txt"), "old");
  std::filesystem::create_symlink("real.txt", dir.file("link.txt"));
  write_text_file_atomically(dir.file("link.txt"), "new");
  EXPECT_TRUE(std::filesystem::is_symlink(dir.file("link.txt")));
  EXPECT_EQ(slurp(dir.file("real.txt")), "new");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"link.txt", "real.txt"}));
}

TEST(AtomicFileGroup, NothingIsReplacedBeforeCommit) {
  TempDir dir;
  spit(dir.file("a.txt"), "old a");
  {
    AtomicFileGroup group;
    write_text_file_atomically(dir.file("a.txt"), "new a");
    write_text_file_atomically(dir.file("b.txt"), "new b");
    EXPECT_EQ(slurp(dir.file("a.txt")), "old a");
    EXPECT_FALSE(std::filesystem::exists(dir.file("b.txt")));
    group.commit();
  }
  EXPECT_EQ(slurp(dir.file("a.txt")), "new a");
  EXPECT_EQ(slurp(dir.file("b.txt")), "new b");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.txt", "b.txt"}));
}

TEST(AtomicFileGroup, AnExceptionBeforeCommitLeavesEveryTargetAsItWas) {
  TempDir dir;
  spit(dir.file("a.txt"), "old a");
  try {
    AtomicFileGroup group;
    write_text_file_atomically(dir.file("a.txt"), "new a");
    write_text_file_atomically(dir.file("b.txt"), "new b");
    write_text_file_atomically(dir.file("no_such_folder/c.txt"), "c");
    group.commit();
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_folder"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(dir.file("a.txt")), "old a");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.txt"});
}

// A rename that fails in the middle of commit() (here: its temporary vanished) puts back the
// targets already replaced: the old file swapped back, the new file removed again.
TEST(AtomicFileGroup, ARenameFailingMidCommitUndoesTheOthers) {
  TempDir dir;
  spit(dir.file("a.txt"), "old a");
  spit(dir.file("c.txt"), "old c");
  std::string msg;
  {
    AtomicFileGroup group;
    write_text_file_atomically(dir.file("a.txt"), "new a");  // replaces an existing file
    write_text_file_atomically(dir.file("b.txt"), "new b");  // creates one
    std::string c_temp;
    {
      AtomicFile c(dir.file("c.txt"));
      c.stream() << "new c";
      c_temp = c.temp_path();
      c.commit();
    }
    ASSERT_TRUE(std::filesystem::remove(c_temp));
    msg = error_of([&] { group.commit(); });
  }
  EXPECT_NE(msg.find("c.txt"), std::string::npos) << msg;
  EXPECT_NE(msg.find("no file was replaced"), std::string::npos) << msg;
  EXPECT_EQ(slurp(dir.file("a.txt")), "old a");
  EXPECT_EQ(slurp(dir.file("c.txt")), "old c");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.txt", "c.txt"}));
}

TEST(TempFileRegistry, RegisteredPathsAreRemovedFilesBeforeFolders) {
  TempDir dir;
  const auto sub = dir.path() / "sub";
  std::filesystem::create_directory(sub);
  const int folder = register_temp_path(sub.string(), true);
  spit((sub / "x.tmp").string(), "x");
  const int file = register_temp_path((sub / "x.tmp").string());
  spit(dir.file("kept.txt"), "kept");
  const int forgotten = register_temp_path(dir.file("kept.txt"));
  unregister_temp_path(forgotten);
  remove_registered_temp_paths();
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"kept.txt"});
  unregister_temp_path(folder);
  unregister_temp_path(file);
}

}  // namespace
}  // namespace fp
