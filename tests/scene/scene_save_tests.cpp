// save_scene replaces the file atomically: it holds the old scene or all of the new one, a link
// stays a link, and a file that cannot be written is a SceneError naming it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "carom/scene.hpp"

namespace carom {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

Scene two_balls(double speed) {
  Scene scene;
  scene.world.boundary = Boundary::box;
  scene.world.lower = {0.0, 0.0};
  scene.world.upper = {10.0, 10.0};
  SceneBall left;
  left.position = {2.0, 5.0};
  left.velocity = {speed, 0.0};
  SceneBall right;
  right.position = {8.0, 5.0};
  scene.balls = {left, right};
  return scene;
}

TEST(SceneSave, ReplacesTheFileThroughALinkAndLeavesNoTemporary) {
  const fs::path dir =
      fs::temp_directory_path() / ("carom_scene_save_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "scenes");
  fs::create_symlink(fs::path("scenes") / "two.json", dir / "link.json");

  save_scene(two_balls(1.0), dir / "link.json");
  save_scene(two_balls(2.5), dir / "link.json");
  EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
  EXPECT_EQ(to_json_text(load_scene(dir / "scenes" / "two.json")), to_json_text(two_balls(2.5)));
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir / "scenes")) ++files;
  EXPECT_EQ(files, 1U) << "a temporary file was left behind";

  try {
    save_scene(two_balls(1.0), dir / "missing" / "two.json");
    ADD_FAILURE() << "saved into a folder that does not exist";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.details().file, (dir / "missing" / "two.json").string());
    EXPECT_THAT(error.details().problem, HasSubstr("cannot create its temporary file"));
  }
  try {
    save_scene(two_balls(1.0), dir / "scenes");
    ADD_FAILURE() << "saved onto a folder";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.details().problem, "is a folder");
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace carom
