// RunFolder: an output folder that describes exactly one run (issue 16).
#include "output/run_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"

namespace vs {
namespace {

namespace fs = std::filesystem;

fs::path fresh(const std::string& name) {
  const fs::path p = fs::path(::testing::TempDir()) / name;
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

void touch(const fs::path& p, const std::string& text = "x") { std::ofstream(p) << text; }

TEST(RunFolder, CommitReplacesThePreviousRunWhole) {
  const fs::path root = fresh("vs_run_folder_replace");
  const fs::path dest = root / "out";
  {
    RunFolder first(dest.string(), "run.json");
    touch(fs::path(first.path()) / "run.json", "1");
    touch(fs::path(first.path()) / "strains_travel_020.00mm.csv");
    first.commit();
  }
  ASSERT_TRUE(fs::exists(dest / "strains_travel_020.00mm.csv"));
  {
    RunFolder second(dest.string(), "run.json");
    // Until the commit the previous run is intact and nothing of the new one is in it.
    touch(fs::path(second.path()) / "run.json", "2");
    EXPECT_TRUE(fs::exists(dest / "strains_travel_020.00mm.csv"));
    second.commit();
  }
  EXPECT_FALSE(fs::exists(dest / "strains_travel_020.00mm.csv"));  // an older run's file
  std::ifstream in(dest / "run.json");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "2");
  // Nothing left beside it: no staging or previous folder.
  int entries = 0;
  for (const auto& e : fs::directory_iterator(root)) entries += e.path() != dest;
  EXPECT_EQ(entries, 0);
}

TEST(RunFolder, AnUncommittedRunLeavesThePreviousFolderUntouched) {
  const fs::path root = fresh("vs_run_folder_abort");
  const fs::path dest = root / "out";
  fs::create_directories(dest);
  touch(dest / "run.json", "old");
  std::string staging;
  {
    RunFolder run(dest.string(), "run.json");
    staging = run.path();
    touch(fs::path(run.path()) / "load_travel.csv");  // a run that dies part-way
  }
  std::ifstream in(dest / "run.json");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "old");
  EXPECT_FALSE(fs::exists(dest / "load_travel.csv"));
  EXPECT_TRUE(fs::exists(fs::path(staging) / "load_travel.csv"));  // kept for inspection
}

TEST(RunFolder, RefusesAForeignFolderAndTheCurrentFolder) {
  const fs::path root = fresh("vs_run_folder_foreign");
  touch(root / "thesis.tex");
  EXPECT_THROW(RunFolder(root.string(), "run.json"), InputError);
  EXPECT_TRUE(fs::exists(root / "thesis.tex"));
  EXPECT_THROW(RunFolder(".", "run.json"), InputError);
  touch(root / "file");
  EXPECT_THROW(RunFolder((root / "file").string(), "run.json"), InputError);
  // An empty folder is fine.
  const fs::path empty = root / "empty";
  fs::create_directories(empty);
  RunFolder ok(empty.string(), "run.json");
  ok.commit();
  EXPECT_TRUE(fs::is_directory(empty));
}

}  // namespace
}  // namespace vs
