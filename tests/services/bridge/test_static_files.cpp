// The page's files: only inside the web directory, with their content types.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "services/bridge/static_files.hpp"

namespace fs = std::filesystem;
using beft::bridge::contentTypeOf;
using beft::bridge::resolveStaticFile;

namespace {

class StaticFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    base_ = fs::temp_directory_path() / ("beft_static_" + std::to_string(getpid()));
    fs::create_directories(base_ / "web" / "js");
    write(base_ / "web" / "index.html", "<html></html>");
    write(base_ / "web" / "js" / "app.js", "1;");
    write(base_ / "secret.txt", "not served");
    fs::create_symlink(base_ / "secret.txt", base_ / "web" / "link.txt");
  }
  void TearDown() override { fs::remove_all(base_); }
  static void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }
  fs::path web() const { return base_ / "web"; }
  fs::path base_;
};

}  // namespace

TEST_F(StaticFiles, ServesFilesInsideTheDirectory) {
  const auto index = resolveStaticFile(web(), "/");
  ASSERT_TRUE(index);
  EXPECT_EQ(index->filename(), "index.html");
  const auto script = resolveStaticFile(web(), "/js/app.js?v=3#top");
  ASSERT_TRUE(script);
  EXPECT_EQ(script->filename(), "app.js");
  EXPECT_FALSE(resolveStaticFile(web(), "/js/"));  // a directory without index.html: nothing
}

TEST_F(StaticFiles, RefusesPathsThatLeaveIt) {
  EXPECT_FALSE(resolveStaticFile(web(), "/../secret.txt"));
  EXPECT_FALSE(resolveStaticFile(web(), "/js/../../secret.txt"));
  EXPECT_FALSE(resolveStaticFile(web(), "/%2e%2e/secret.txt"));
  EXPECT_FALSE(resolveStaticFile(web(), "/..%2fsecret.txt"));
  EXPECT_FALSE(resolveStaticFile(web(), "/js/../index.html"));  // ".." is refused even where it stays inside
  EXPECT_FALSE(resolveStaticFile(web(), "/link.txt"));          // a link pointing out
  EXPECT_FALSE(resolveStaticFile(web(), "secret.txt"));
  EXPECT_FALSE(resolveStaticFile(web(), "/index.html%00.js"));
  EXPECT_FALSE(resolveStaticFile(web(), "/%zz"));
  EXPECT_FALSE(resolveStaticFile(web(), "/missing.html"));
  EXPECT_FALSE(resolveStaticFile(base_ / "nowhere", "/index.html"));
}

TEST(ContentTypes, ByExtension) {
  EXPECT_EQ(contentTypeOf("a/index.HTML"), "text/html; charset=utf-8");
  EXPECT_EQ(contentTypeOf("app.js"), "text/javascript; charset=utf-8");
  EXPECT_EQ(contentTypeOf("style.css"), "text/css; charset=utf-8");
  EXPECT_EQ(contentTypeOf("x.wasm"), "application/wasm");
  EXPECT_EQ(contentTypeOf("x.png"), "image/png");
  EXPECT_EQ(contentTypeOf("blob"), "application/octet-stream");
}
