#include "image_files/PngFile.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace ivshadow {
namespace {

using test::readText;

TEST(VariantsCommand, RendersEveryGoodVariantAndReportsTheBadOneWithItsLine) {
  const std::string dir = test::outputDir() + "/out";
  const std::string variants =
      std::string(IVSHADOW_SOURCE_DIR) + "/tests/variants/with_a_bad_variant.variants";
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "variants", test::scenesDir() + "/coloured_shadows.iv",
                 variants, "-o", dir, "--size", "96x72", "--frames", "1", "--jobs", "2"});
  // Some variant had bad input: exit 2, after the others rendered.
  EXPECT_EQ(result.exitCode, 2) << result.err;
  const std::vector<std::string> errors = test::lines(result.err);
  bool reported = false;
  for (const std::string& line : errors)
    reported |= line.find(variants + ":7: error: variant typo: ") != std::string::npos &&
                line.find("no field 'colour'") != std::string::npos;
  EXPECT_TRUE(reported) << result.err;
  EXPECT_NE(result.out.find("rendered 3 of 4 variants"), std::string::npos) << result.out;

  for (const char* name : {"dim", "size-32", "size-64"}) {
    const Image image = readPng(dir + "/" + name + ".png");
    EXPECT_EQ(image.width(), 96) << name;
  }
  EXPECT_FALSE(test::fileExists(dir + "/typo.png"));

  const std::vector<std::string> csv = test::lines(readText(dir + "/variants.csv"));
  ASSERT_EQ(csv.size(), 5u);
  EXPECT_EQ(csv[0].rfind("variant,assignments,status,shadow_method,frame_ms_median,", 0), 0u);
  EXPECT_EQ(csv[1].rfind("\"dim\",\"Lamp.intensity=0.4\",ok,", 0), 0u) << csv[1];
  EXPECT_EQ(csv[2].rfind("\"typo\",\"Lamp.intensity=0.7; Lamp.colour=1 0 0\",failed,", 0), 0u)
      << csv[2];
  EXPECT_NE(csv[3].find("\"size-32\""), std::string::npos);
  const std::string html = readText(dir + "/index.html");
  EXPECT_NE(html.find("<img src=\"size-64.png\""), std::string::npos);
  EXPECT_NE(html.find("no field"), std::string::npos);
  // Nothing but the images, the two reports and the manifests is left behind.
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 6);
  int manifests = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir + "/manifests")) {
    (void)entry;
    ++manifests;
  }
  EXPECT_EQ(manifests, 5);  // one a variant, failed ones too, and the plan
}

// A rerun keeps what is done for the same inputs and renders the failed variant again; other
// inputs (here the frame count, part of each variant's hash) make every manifest stale.
TEST(VariantsCommand, ARerunKeepsCurrentVariantsAndRendersStaleOnes) {
  const std::string dir = test::outputDir() + "/out";
  const std::string variants =
      std::string(IVSHADOW_SOURCE_DIR) + "/tests/variants/with_a_bad_variant.variants";
  const std::vector<std::string> command = {test::ivshadowExe(),
                                            "variants",
                                            test::scenesDir() + "/coloured_shadows.iv",
                                            variants,
                                            "-o",
                                            dir,
                                            "--size",
                                            "48x36",
                                            "--frames",
                                            "1"};
  EXPECT_EQ(test::run(command).exitCode, 2);
  const test::ProcessResult again = test::run(command);
  EXPECT_EQ(again.exitCode, 2) << again.err;
  EXPECT_NE(again.out.find("rendered 3 of 4 variants to " + dir +
                           " (variants.csv, index.html, 3 kept from an earlier run)"),
            std::string::npos)
      << again.out;
  EXPECT_NE(again.err.find("variant typo: "), std::string::npos) << again.err;
  std::vector<std::string> stale = command;
  stale.back() = "2";
  const test::ProcessResult changed = test::run(stale);
  EXPECT_EQ(changed.exitCode, 2) << changed.err;
  EXPECT_EQ(changed.out.find("kept"), std::string::npos) << changed.out;
  // A shard of a finished sweep has nothing to do, and says so: it once printed "rendered 0 of
  // 0 variants", which reads as a failure.
  std::vector<std::string> done = stale;
  done.insert(done.end(), {"--shard", "0/2"});
  const test::ProcessResult finished = test::run(done);
  EXPECT_EQ(finished.exitCode, 0) << finished.err;
  EXPECT_EQ(finished.out,
            "shard 0/2: nothing left to render; all 2 of its variants were already rendered to " +
                dir + "; `ivshadow variants-merge " + dir + "` writes the reports\n");
  done.back() = "4/5";
  const test::ProcessResult empty = test::run(done);
  EXPECT_EQ(empty.exitCode, 0) << empty.err;
  EXPECT_NE(empty.out.find("shard 4/5 holds none of the sweep's 4 variants; nothing to render"),
            std::string::npos)
      << empty.out;
  EXPECT_EQ(
      test::run({test::ivshadowExe(), "variants-merge", "--status", dir}).out,
      dir + ": done 3, failed 1, pending 0 of 4 variants\n  " + variants +
          ":7: error: variant typo: --set 'Lamp.colour=1 0 0': error: node 'Lamp' "
          "(DeepShadowLight) has no field 'colour' (its fields: bias, color, colorModel, "
          "farRadius, filter, filterSize, intensity, layerOverflow, location, maxLayers, method, "
          "nearRadius, on, precision, resolution, shadowColor, slices)\n");
}

// --shard and --only name what is wrong with them before anything is rendered.
TEST(VariantsCommand, ABadShardOrVariantNameIsRefusedBeforeRendering) {
  const std::string dir = test::outputDir() + "/out";
  const std::string variants =
      std::string(IVSHADOW_SOURCE_DIR) + "/tests/variants/with_a_bad_variant.variants";
  const std::vector<std::string> command = {test::ivshadowExe(),
                                            "variants",
                                            test::scenesDir() + "/coloured_shadows.iv",
                                            variants,
                                            "-o",
                                            dir};
  for (const char* shard : {"4/4", "1", "2/1", "0/0", "a/b"}) {
    std::vector<std::string> bad = command;
    bad.insert(bad.end(), {"--shard", shard});
    const test::ProcessResult result = test::run(bad);
    EXPECT_EQ(result.exitCode, 2) << shard;
    EXPECT_NE(result.err.find(std::string("--shard ") + shard + ": error: expected K/N"),
              std::string::npos)
        << result.err;
  }
  std::vector<std::string> unknown = command;
  unknown.insert(unknown.end(), {"--only", "bright"});
  const test::ProcessResult result = test::run(unknown);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.err.find("--only bright: error: " + variants + " has no variant of that name"),
            std::string::npos)
      << result.err;
  std::vector<std::string> slurm = command;
  slurm.insert(slurm.end(), {"--slurm", dir + "-jobs", "--shard", "0/2"});
  const test::ProcessResult both = test::run(slurm);
  EXPECT_EQ(both.exitCode, 2);
  EXPECT_NE(both.err.find("--slurm: error: writes the scripts of the whole sweep"),
            std::string::npos)
      << both.err;
  EXPECT_FALSE(test::fileExists(dir + "-jobs"));
  std::vector<std::string> shards = command;
  shards.insert(shards.end(), {"--shards", "4"});
  const test::ProcessResult alone = test::run(shards);
  EXPECT_EQ(alone.exitCode, 2);
  EXPECT_NE(alone.err.find("--shards: error: only for --slurm DIR"), std::string::npos)
      << alone.err;
  EXPECT_FALSE(test::fileExists(dir));
  const test::ProcessResult merge = test::run({test::ivshadowExe(), "variants-merge", dir});
  EXPECT_EQ(merge.exitCode, 2);
  EXPECT_NE(merge.err.find(dir + "/manifests/plan.json: error: no plan of a sweep here"),
            std::string::npos)
      << merge.err;
}

// An output directory that cannot be one is named with what was expected, before anything is
// rendered: an empty -o once rendered the whole sweep into the current directory.
TEST(VariantsCommand, AnOutputDirectoryThatIsAFileOrEmptyIsRefusedNamingIt) {
  const std::string dir = test::outputDir();
  const std::string file = test::writeOutputFile("a-file", "not a directory\n");
  const std::vector<std::string> command = {
      test::ivshadowExe(), "variants", test::scenesDir() + "/coloured_shadows.iv",
      std::string(IVSHADOW_SOURCE_DIR) + "/tests/variants/with_a_bad_variant.variants"};
  const struct {
    std::vector<std::string> arguments;
    std::string expected;
  } cases[] = {
      {{"-o", ""},
       "-o '': error: expected a directory for the sweep's pictures, manifests and reports, got "
       "an empty name"},
      {{"-o", file},
       file +
           ": error: -o expects a directory for the sweep's pictures, manifests and reports, "
           "but " +
           file + " is a file"},
      {{"-o", file + "/sweep"}, "but " + file + " (in " + file + "/sweep) is a file"},
      {{"-o", dir + "/out", "--slurm", file},
       file + ": error: --slurm expects a directory for the job scripts, but " + file +
           " is a file"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> arguments = command;
    arguments.insert(arguments.end(), c.arguments.begin(), c.arguments.end());
    const test::ProcessResult result = test::run(arguments);
    EXPECT_EQ(result.exitCode, 2) << c.expected;
    ASSERT_EQ(test::lines(result.err).size(), 1u) << result.err;
    EXPECT_NE(result.err.find(c.expected), std::string::npos) << result.err;
    EXPECT_TRUE(result.out.empty()) << result.out;
  }
  EXPECT_FALSE(test::fileExists(dir + "/out"));
  EXPECT_FALSE(test::fileExists("variants.csv")) << "nothing written where the test runs";
}

// submit.sh names the job scripts absolutely (docs/VARIANTS.md): written with a relative
// --slurm, it submitted them relative to wherever the user stood when running it.
TEST(VariantsCommand, SlurmScriptsNameEveryPathAbsolutely) {
  namespace fs = std::filesystem;
  const std::string dir = test::outputDir();
  const std::string jobs = fs::relative(dir + "/jobs").string();
  const std::string out = fs::relative(dir + "/out").string();
  ASSERT_NE(jobs.front(), '/');
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "variants", test::scenesDir() + "/coloured_shadows.iv",
                 std::string(IVSHADOW_SOURCE_DIR) + "/tests/variants/with_a_bad_variant.variants",
                 "-o", out, "--slurm", jobs, "--shards", "2"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::string absoluteJobs = fs::absolute(jobs).lexically_normal().string();
  EXPECT_NE(result.out.find("sh " + absoluteJobs + "/submit.sh"), std::string::npos) << result.out;
  const std::string submit = readText(dir + "/jobs/submit.sh");
  EXPECT_NE(submit.find("sbatch --parsable " + absoluteJobs + "/variants.sbatch"),
            std::string::npos)
      << submit;
  EXPECT_NE(submit.find(" " + absoluteJobs + "/merge.sbatch"), std::string::npos) << submit;
  EXPECT_EQ(submit.find(" " + jobs + "/"), std::string::npos) << submit;
}

// Splits a CSV line at commas outside double quotes; quotes are dropped.
std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      fields.emplace_back();
    else
      fields.back() += c;
  }
  return fields;
}

// A setting that does nothing on the path a variant renders by (a map's resolution in a group
// that traces) is said once for the sweep, naming the variant, and shown in its report.
TEST(VariantsCommand, ASettingThatDoesNothingIsSaidOnceAndReported) {
  const std::string dir = test::outputDir() + "/out";
  const std::string file = test::outputDir() + "/idle.variants";
  std::ofstream(file) << "sweep idle Lamp.resolution = 128 | 256\n  Scene.renderer = TRACER\n"
                         "variant acting\n  Lamp.intensity = 0.5\n";
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "variants", test::scenesDir() + "/coloured_shadows.iv", file,
                 "-o", dir, "--size", "64x48", "--frames", "1", "--jobs", "2"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::string warning =
      "DeepShadowLight 'Lamp': resolution does nothing: TransparentShadowGroup 'Scene' traces "
      "its children (renderer TRACER)";
  std::size_t said = 0;
  for (const std::string& line : test::lines(result.err))
    if (line.find(warning) != std::string::npos) ++said;
  EXPECT_EQ(said, 1u) << result.err;
  const std::string html = readText(dir + "/index.html");
  std::size_t shown = 0;
  for (std::size_t at = html.find(warning); at != std::string::npos;
       at = html.find(warning, at + 1))
    ++shown;
  EXPECT_EQ(shown, 2u) << "under each of the two variants that set it";
}

TEST(VariantsCommand, ACrossedSweepRendersTheGridWithColumnsOfEachMethod) {
  const std::string dir = test::outputDir() + "/out";
  const std::string file = test::outputDir() + "/grid.variants";
  // GL's path, where the light's method acts (the default, AUTO, traces on a software
  // rasteriser, where it does not).
  std::ofstream(file) << "sweep grid Lamp.method = MAP | RAYS * Lamp.intensity = 0.5 | 1\n"
                         "  Lamp.resolution = 512\n  Scene.renderer = RASTER\n";
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "variants", test::scenesDir() + "/coloured_shadows.iv", file,
                 "-o", dir, "--size", "64x48", "--frames", "1", "--jobs", "2"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::vector<std::string> csv = test::lines(readText(dir + "/variants.csv"));
  ASSERT_EQ(csv.size(), 5u);
  EXPECT_EQ(csv[0],
            "variant,assignments,status,shadow_method,frame_ms_median,dsm_build_ms,rays_ms,"
            "bvh_build_ms,peel_ms,dsm_bytes,bvh_bytes,dsm_layers_used,image");
  const char* names[] = {"grid-MAP-0.5", "grid-MAP-1", "grid-RAYS-0.5", "grid-RAYS-1"};
  const std::string html = readText(dir + "/index.html");
  for (int i = 0; i < 4; ++i) {
    const std::vector<std::string> row = csvFields(csv[std::size_t(i) + 1]);
    ASSERT_EQ(row.size(), 13u) << csv[std::size_t(i) + 1];
    EXPECT_EQ(row[0], names[i]);
    EXPECT_EQ(readPng(dir + "/" + row[12]).width(), 64);
    const bool rays = i >= 2;
    EXPECT_EQ(row[1], std::string("Lamp.method=") + (rays ? "RAYS" : "MAP") + "; Lamp.intensity=" +
                          (i % 2 ? "1" : "0.5") + "; Lamp.resolution=512; Scene.renderer=RASTER");
    EXPECT_EQ(row[3], rays ? "RAYS" : "MAP");
    // A method's columns are filled for the lights that use it and empty otherwise.
    EXPECT_EQ(row[5].empty(), rays) << "dsm_build_ms: " << csv[std::size_t(i) + 1];
    EXPECT_EQ(row[6].empty(), !rays) << "rays_ms: " << csv[std::size_t(i) + 1];
    EXPECT_EQ(row[7].empty(), !rays) << "bvh_build_ms";
    EXPECT_EQ(row[9].empty(), rays) << "dsm_bytes";
    EXPECT_EQ(row[10].empty(), !rays) << "bvh_bytes";
    EXPECT_EQ(row[11].empty(), rays) << "dsm_layers_used";
    // What the method keeps is not nothing: a map of 512^2 texels a face and layer, the
    // casters' BVH. Byte counts are written whole: the map's millions of bytes once read
    // 6.29146e+06.
    const std::string& bytes = rays ? row[10] : row[9];
    EXPECT_GT(std::stod(bytes), 0.0);
    EXPECT_EQ(bytes.find_first_not_of("0123456789"), std::string::npos) << bytes;
    if (!rays) EXPECT_GT(std::stod(bytes), 1e6) << bytes;
    const std::size_t at = html.find("<figure id=\"" + std::string(names[i]) + "\">");
    ASSERT_NE(at, std::string::npos);
    const std::string caption = html.substr(at, html.find("</figure>", at) - at);
    EXPECT_EQ(caption.find("rays traced in") != std::string::npos, rays) << caption;
    EXPECT_EQ(caption.find("map built in") != std::string::npos, !rays) << caption;
  }
}

// Ctrl-C (SIGINT to the command alone here; a terminal sends it to the renders too) stops the
// run: no render is started after it, the running ones are interrupted, and nothing is left
// of them (no .NAME.log, .NAME.stats.json or temporary picture), no report is written, exit
// 130. Variants finished before it keep their pictures.
TEST(VariantsCommand, AnInterruptedRunLeavesNoScratchFilesAndNoReport) {
  const std::string dir = test::outputDir();
  const std::string file = dir + "/many.variants";
  std::ofstream(file) << "sweep light Lamp.intensity = 0.1 .. 1.0 step 0.1\n";
  const std::string out = dir + "/out";
  const int pid = test::startProcess(
      {test::ivshadowExe(), "variants", test::scenesDir() + "/coloured_shadows.iv", file, "-o", out,
       "--size", "160x120", "--jobs", "2"},
      {}, dir + "/variants.out", dir + "/variants.err");
  ASSERT_GT(pid, 0);
  // Some renders are under way once their logs exist.
  for (int i = 0; i < 200; ++i) {
    bool started = false;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(out, ec))
      started = started || entry.path().extension() == ".log";
    if (started) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(pid, SIGINT);
  EXPECT_EQ(test::waitForProcess(pid), 130);
  EXPECT_NE(readText(dir + "/variants.err").find("ivshadow: interrupted: "), std::string::npos)
      << readText(dir + "/variants.err");
  int pictures = 0;
  for (const auto& entry : std::filesystem::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    EXPECT_NE(name[0], '.') << "left behind: " << name;
    EXPECT_NE(name, "variants.csv");
    EXPECT_NE(name, "index.html");
    pictures += entry.path().extension() == ".png" ? 1 : 0;
  }
  EXPECT_LT(pictures, 10) << "the run was not interrupted";
}

// A manifest cut short, empty or wrongly typed was "not rendered yet" to variants-merge, or
// a raw json.exception: the merge (and --status) now names the file and what is wrong, exit
// 2, and writes no report; a run that renders takes it as not rendered and replaces it.
TEST(VariantsCommand, ABrokenManifestIsNamedByTheMergeAndRenderedAgainByARun) {
  const std::string dir = test::outputDir();
  const std::string file = dir + "/two.variants", out = dir + "/out";
  std::ofstream(file) << "variant a\n  Lamp.intensity = 0.5\nvariant b\n";
  const std::vector<std::string> sweep = {test::ivshadowExe(),
                                          "variants",
                                          test::scenesDir() + "/lit_plane.iv",
                                          file,
                                          "-o",
                                          out,
                                          "--size",
                                          "16x12"};
  ASSERT_EQ(test::run(sweep).exitCode, 0);
  const std::string manifest = out + "/manifests/a.json";
  const std::string good = readText(manifest);
  std::string typed = good;
  typed.replace(typed.find("\"exit_code\": 0"), 14, "\"exit_code\": \"0\"");
  std::string other = good;
  other.replace(other.find("\"variant\": \"a\""), 14, "\"variant\": \"b\"");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {good.substr(0, good.size() / 2),
       "the manifest of variant a is not valid JSON (cut short?): "
       "parse error at line"},
      {"", "the manifest of variant a is empty"},
      {typed, "field \"exit_code\" is a string; expected a whole number"},
      {"[1, 2]\n", "the manifest of variant a must be a JSON object; found an array"},
      {other, "the manifest names the variant \"b\", not \"a\""},
  };
  for (const auto& [text, expected] : cases) {
    std::filesystem::remove(out + "/variants.csv");
    std::ofstream(manifest, std::ios::binary | std::ios::trunc) << text;
    for (const bool status : {false, true}) {
      std::vector<std::string> merge = {test::ivshadowExe(), "variants-merge", out};
      if (status) merge.insert(merge.begin() + 2, "--status");
      const test::ProcessResult result = test::run(merge);
      EXPECT_EQ(result.exitCode, 2) << expected << "\n" << result.err;
      EXPECT_EQ(result.err.rfind(manifest + ": error: " + expected, 0), 0u) << result.err;
      EXPECT_EQ(test::lines(result.err).size(), 1u) << result.err;
      EXPECT_FALSE(test::fileExists(out + "/variants.csv"));
    }
  }
  // A run renders the variant again and writes a good manifest over the broken one.
  const test::ProcessResult again = test::run(sweep);
  EXPECT_EQ(again.exitCode, 0) << again.err;
  EXPECT_NE(again.out.find("1 kept from an earlier run"), std::string::npos) << again.out;
  EXPECT_EQ(test::run({test::ivshadowExe(), "variants-merge", out}).exitCode, 0);
}

// A variant named "plan" overwrote manifests/plan.json and broke the merge: such names are
// refused at their line before anything is written.
TEST(VariantsCommand, AVariantNamedLikeTheSweepsOwnFilesIsRefusedAtItsLine) {
  const std::string dir = test::outputDir();
  const std::string file = dir + "/plan.variants", out = dir + "/out";
  std::ofstream(file) << "variant a\nvariant plan\n  Lamp.intensity = 0.5\n";
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "variants", test::scenesDir() + "/lit_plane.iv", file, "-o",
                 out, "--size", "16x12"});
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_EQ(result.err, file +
                            ":2: error: variant name \"plan\" is taken by the sweep's own "
                            "manifests/plan.json; choose another\n");
  EXPECT_FALSE(test::fileExists(out));
}

TEST(VariantsCommand, ABadVariantsFileStopsBeforeRendering) {
  const std::string dir = test::outputDir() + "/out";
  const std::string file = test::outputDir() + "/bad.variants";
  std::ofstream(file) << "variant a\n  Lamp.intensity 0.5\n";
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "variants", test::scenesDir() + "/coloured_shadows.iv", file,
                 "-o", dir});
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_EQ(test::lines(result.err).size(), 1u) << result.err;
  EXPECT_NE(result.err.find(file + ":2: error: expected NODE.field = VALUE"), std::string::npos)
      << result.err;
  EXPECT_FALSE(test::fileExists(dir));
}

}  // namespace
}  // namespace ivshadow
