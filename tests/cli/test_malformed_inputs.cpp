// The malformed-input table: bad arguments and bad files given to every tool (c2f-stereo,
// c2f-segment, c2f-synthetic). Each case asserts the exit code, that the message names the
// input and says what was expected, and that the outputs of an earlier good run in the folder
// it was pointed at are byte-identical afterwards (no file changed, added or removed).

#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "support/run_tool.hpp"
#include "support/synthetic_segmentation.hpp"
#include "support/synthetic_stereo.hpp"

namespace fs = std::filesystem;

namespace {

struct Case {
  const char* tool;       ///< "stereo", "segment" or "synthetic"
  std::string arguments;  ///< with {dir}, {left}, {right}, {image}, {seeds}, {gt}, {out}
  int exit_code;
  std::vector<std::string> expected;  ///< parts of the message (the input and what was expected)
};

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

/// Every file below `root` with its bytes.
std::map<std::string, std::string> snapshot(const fs::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    files[fs::relative(entry.path(), root).string()] =
        entry.is_regular_file() ? read_bytes(entry.path()) : std::string("<folder>");
  }
  return files;
}

std::string substitute(std::string text, const std::map<std::string, std::string>& values) {
  for (const auto& [key, value] : values) {
    for (std::size_t at; (at = text.find(key)) != std::string::npos;)
      text.replace(at, key.size(), value);
  }
  return text;
}

/// The fixture: good inputs, bad files and folders, and the good runs' outputs.
struct Inputs {
  fs::path dir = fs::temp_directory_path() / "c2f-test-malformed";
  std::map<std::string, std::string> names;

  Inputs() {
    fs::remove_all(dir);
    const auto pair = c2f::test::write_synthetic_pair(dir, 48, 32, 2, 6, 3);
    cv::imwrite((dir / "small.png").string(), pair.left(cv::Rect(0, 0, 20, 20)));
    cv::imwrite((dir / "small-grey.png").string(), cv::Mat(20, 20, CV_8U, cv::Scalar(8)));
    cv::imwrite((dir / "deep.png").string(), cv::Mat(32, 48, CV_16UC3, cv::Scalar(9, 900, 9000)));
    cv::imwrite((dir / "big.png").string(), cv::Mat(3000, 4000, CV_8UC3, cv::Scalar(90, 40, 20)));
    write_bytes(dir / "empty.png", "");
    {  // A PFM whose scale says big-endian over little-endian floats of 37.25.
      std::string pfm = "Pf\n48 32\n1.0\n";
      const float value = 37.25F;
      for (int i = 0; i < 48 * 32; ++i)
        pfm.append(reinterpret_cast<const char*>(&value), sizeof value);
      write_bytes(dir / "flipped.pfm", pfm);
    }
    write_bytes(dir / "text.png", "not an image\n");
    const std::string png = read_bytes(dir / "left.png");
    write_bytes(dir / "truncated.png", png.substr(0, png.size() / 2));
    // A PNG header saying 40000x30000 (1.2e9 pixels), and nothing after it.
    write_bytes(dir / "huge-header.ppm", "P6\n# a comment\n999999999 999999999\n255\n");
    write_bytes(dir / "huge-header.png", std::string("\x89PNG\r\n\x1A\n\0\0\0\x0DIHDR", 16) +
                                             std::string("\0\0\x9C\x40\0\0\x75\x30", 8) +
                                             std::string("\x08\x02\0\0\0\0\0\0\0", 9));

    const auto seg = c2f::test::write_synthetic_segmentation(dir / "seg", 40, 30, 3);
    cv::Mat white(30, 40, CV_8UC3, cv::Scalar(255, 255, 255));
    cv::imwrite((dir / "seeds-none.png").string(), white);
    cv::Mat one = white.clone();
    cv::line(one, {5, 5}, {20, 5}, cv::Scalar(0, 0, 255), 2);
    cv::imwrite((dir / "seeds-one.png").string(), one);
    cv::Mat green = one.clone();  // red and blue seeds, and a green dot --binary has no meaning for
    cv::line(green, {5, 20}, {20, 20}, cv::Scalar(255, 0, 0), 2);
    cv::imwrite((dir / "seeds-binary.png").string(), green);
    green.at<cv::Vec3b>(12, 30) = cv::Vec3b(0, 200, 0);
    cv::imwrite((dir / "seeds-green.png").string(), green);
    cv::imwrite((dir / "gt-unknown.png").string(), cv::Mat(32, 48, CV_8U, cv::Scalar(0)));
    cv::imwrite((dir / "mask-none.png").string(), cv::Mat(32, 48, CV_8U, cv::Scalar(0)));
    cv::imwrite((dir / "mask-grey.png").string(), cv::Mat(32, 48, CV_8U, cv::Scalar(128)));
    cv::imwrite((dir / "mask-red.png").string(), cv::Mat(32, 48, CV_8UC3, cv::Scalar(0, 0, 255)));
    cv::Mat grey_gt(30, 40, CV_8U, cv::Scalar(255));
    grey_gt.at<std::uint8_t>(3, 4) = 77;
    cv::imwrite((dir / "gt-grey77.png").string(), grey_gt);
    cv::Mat odd_gt = cv::imread(seg.gt);
    odd_gt.at<cv::Vec3b>(2, 2) = cv::Vec3b(10, 200, 30);  // a colour no seed has
    cv::imwrite((dir / "gt-odd.png").string(), odd_gt);

    // Scene tables: good rows pointing at the pair, and one defect each.
    const std::string header = "year,scene,dir,width,height,scale,gt_divisor,files\n";
    const auto table = [&](const char* name, const std::string& rows) {
      fs::create_directories(dir / name);
      write_bytes(dir / name / "scenes.csv", header + rows);
    };
    // A user's own folder, and a FIFO nobody reads.
    fs::create_directories(dir / "out" / "users");
    write_bytes(dir / "out" / "users" / "error.png", "the user's own picture");
    fs::create_directories(dir / "out" / "empty");
    const std::string fifo = (dir / "fifo").string();
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);

    table("scenes-good", "2003,Pair,pair,48,32,native,4,left.png right.png\n");
    table("scenes-width", "2003,Pair,pair,48x,32,native,4,left.png\n");
    table("scenes-fields", "2003,Pair,pair,48,32\n");
    table("scenes-divisor", "2003,Pair,pair,48,32,native,inf,left.png\n");
    table("scenes-twice", "2003,Pair,a,48,32,native,4,x\n2005,Pair,b,48,32,native,4,x\n");
    // Scene tables that are no regular file: refused at once, never waited on or read.
    fs::create_directories(dir / "scenes-fifo");
    REQUIRE(::mkfifo((dir / "scenes-fifo" / "scenes.csv").c_str(), 0600) == 0);
    fs::create_directories(dir / "scenes-zero");
    fs::create_symlink("/dev/zero", dir / "scenes-zero" / "scenes.csv");
    fs::create_directories(dir / "scenes-folder" / "scenes.csv");
    fs::create_directories(dir / "scenes-nocolumn");
    write_bytes(dir / "scenes-nocolumn" / "scenes.csv", "year,scene\n2003,Pair\n");

    names = {{"{dir}", dir.string()},
             {"{left}", (dir / "left.png").string()},
             {"{right}", (dir / "right.png").string()},
             {"{image}", seg.image},
             {"{seeds}", seg.seeds},
             {"{gt}", seg.gt},
             {"{out}", (dir / "out").string()}};
  }
};

std::string binary(const char* tool) {
  const std::string name = tool;
  return name == "stereo"    ? C2F_STEREO_BINARY
         : name == "segment" ? C2F_SEGMENT_BINARY
                             : C2F_SYNTHETIC_BINARY;
}

std::vector<Case> stereo_cases() {
  const std::string pair = "{left} {right} -o {out}/stereo ";
  const std::string scene = "-o {out}/stereo --scene Pair --data {dir}/";
  return {
      {"stereo",
       "{dir}/missing.png {right} -o {out}/stereo",
       2,
       {"LEFT: file '", "missing.png' does not exist"}},
      {"stereo",
       "{left} {dir}/missing.png -o {out}/stereo",
       2,
       {"RIGHT: file '", "missing.png' does not exist"}},
      {"stereo", "{dir} {right} -o {out}/stereo", 2, {"LEFT: file '", "' is a folder, not a file"}},
      // A name longer than the system allows (found by fuzzing: an uncaught filesystem_error).
      {"stereo",
       "{left} {dir}/" + std::string(300, 'r') + ".png -o {out}/stereo",
       2,
       {"RIGHT: file '", "' cannot be examined (File name too long)"}},
      {"stereo", "{left} -o {out}/stereo", 2, {"give LEFT and RIGHT images, or --scene NAME"}},
      {"stereo", pair + "{left}", 2, {"unexpected argument '", "takes at most 2 (LEFT RIGHT)"}},
      {"stereo", "{left} {right}", 2, {"-o/--out: an output directory is required"}},
      {"stereo",
       "{dir}/empty.png {right} -o {out}/stereo",
       2,
       {"empty.png' could not be read as an image"}},
      {"stereo",
       "{dir}/text.png {right} -o {out}/stereo",
       2,
       {"text.png' could not be read as an image"}},
      {"stereo",
       "{dir}/truncated.png {right} -o {out}/stereo",
       2,
       {"truncated.png' could not be read as an image"}},
      {"stereo", "{left} {dir}/small.png -o {out}/stereo", 2, {"LEFT is 48x32, RIGHT is 20x20"}},
      {"stereo",
       "{dir}/deep.png {right} -o {out}/stereo",
       2,
       {"deep.png' has 16-bit channels; expected 8 bits per channel"}},
      {"stereo", pair + "--labels 1", 2, {"--labels: expected 0 or 2-256, got 1"}},
      {"stereo", pair + "--labels 1e3", 2, {"--labels: expected an integer", "got '1e3'"}},
      {"stereo", pair + "--labels abc", 2, {"--labels: expected an integer", "got 'abc'"}},
      {"stereo", pair + "--labels 300", 2, {"--labels: expected an integer in [0, 256]"}},
      {"stereo", pair + "--labels", 2, {"the required argument for option '--labels' is missing"}},
      {"stereo",
       pair + "--time-limit nan",
       2,
       {"--time-limit: expected a finite number in [0, 1e+07], got 'nan'"}},
      {"stereo", pair + "--time-limit -1", 2, {"--time-limit: expected a finite number"}},
      {"stereo", pair + "--time-limit 1e999", 2, {"--time-limit: ", "got '1e999'"}},
      {"stereo", pair + "--max-steps -3", 2, {"--max-steps: expected an integer in [0, "}},
      {"stereo", pair + "--max-steps 5x", 2, {"--max-steps: ", "got '5x'"}},
      {"stereo", pair + "--plateau 0", 2, {"--plateau: expected an integer in [1, "}},
      {"stereo",
       pair + "--plateau soon",
       2,
       {"--plateau: expected an integer in [1, ", "or rate, got 'soon'"}},
      {"stereo",
       pair + "--plateau-tolerance 1",
       2,
       {"--plateau-tolerance: expected a finite number in [0, 1), got '1'"}},
      {"stereo", pair + "--final-plateau 2.5", 2, {"--final-plateau: ", "got '2.5'"}},
      {"stereo", pair + "--downscale 0", 2, {"--downscale: expected an integer in [1, 1024]"}},
      {"stereo", pair + "--downscale 100", 2, {"downscale: 48x32 views shrunk by 100"}},
      {"stereo",
       pair + "--gt {left} --gt-divisor 1e-300",
       2,
       {"--gt-divisor: expected 0 (by the file) or a number in [1/1024, 65536], got 1e-300"}},
      {"stereo",
       pair + "--gt {dir}/small-grey.png --gt-divisor 256",
       2,
       {"small-grey.png' is an 8-bit PNG: divided by 256 every disparity would be below one "
        "pixel"}},
      {"stereo",
       pair + "--gt {dir}/flipped.pfm",
       2,
       {"flipped.pfm' holds the disparity ", "is the sign of its scale (the byte order) right?"}},
      {"stereo", pair + "--gt {left} --gt-divisor inf", 2, {"--gt-divisor: ", "got 'inf'"}},
      {"stereo",
       pair + "--gt {dir}/missing.png",
       2,
       {"--gt: file '", "missing.png' does not exist"}},
      {"stereo", pair + "--gt {dir}/small-grey.png", 2, {"small-grey.png' is 20x20"}},
      {"stereo",
       pair + "--gt {left}",
       2,
       {"left.png' has 3 channels", "expected one channel of 8 or 16 bits"}},
      {"stereo", pair + "--mask {left}", 2, {"a right-view GT or a mask needs the left-view GT"}},
      {"stereo",
       "{dir}/huge-header.png {right} -o {out}/stereo",
       2,
       {"image '",
        "huge-header.png' is 40000x30000 pixels by its header, more than an image "
        "may have"}},
      {"stereo",
       "{dir}/big.png {right} -o {out}/stereo --memory 0.01",
       2,
       {"image '",
        "big.png' needs 45.8 MiB decoded (4000x3000 pixels by its header), more than "
        "the 10.2 MiB the run's memory budget allows for one input"}},
      {"stereo",
       "{dir}/huge-header.ppm {right} -o {out}/stereo",
       2,
       {"image '", "huge-header.ppm' is 999999999x999999999 pixels by its header"}},
      {"stereo",
       "{left} {left} -o {out}/stereo",
       2,
       {"LEFT '", "', RIGHT '", "every pixel matches some disparity perfectly",
        "are the two views identical"}},
      // Outputs over inputs and over each other (each was overwritten or lost, exit 0).
      {"stereo", pair + "--trace {left}", 2, {"--trace '", "' is the same file as LEFT '"}},
      {"stereo",
       pair + "--export-uai {right}",
       2,
       {"--export-uai '", "' is the same file as RIGHT '", "would overwrite an input"}},
      {"stereo",
       pair + "--trace {out}/stereo/disparity.png",
       2,
       {"is disparity.png, a file the run writes into"}},
      {"stereo",
       pair + "--trace {out}/stereo/summary.txt",
       2,
       {"is summary.txt, a file the run writes into"}},
      {"stereo",
       pair + "--trace {out}/stereo/partition-level0.png",
       2,
       {"is partition-level0.png, a file the run writes into"}},
      {"stereo",
       pair + "--trace {dir}/both.out --export-uai {dir}/both.out",
       2,
       {"--trace and --export-uai name one file '"}},
      // Folders the tool does not own, and outputs that are not files.
      {"stereo",
       "{left} {right} -o {out}/users --labels 8",
       1,
       {"the output folder '", "users' is not empty and was not written by a c2f tool"}},
      {"stereo",
       "{left} {right} -o {out}/segment --labels 8",
       1,
       {"the output folder '", "segment' holds the outputs of c2f-segment, not of c2f-stereo"}},
      {"stereo", "{left} {right} -o / --labels 8", 1, {"the output folder '/' is the root folder"}},
      {"stereo", pair + "--trace {dir}", 2, {"--trace '", "' is a folder, not a file"}},
      {"stereo",
       pair + "--trace {dir}/fifo --labels 8",
       2,
       {"--trace: '", "fifo' is a FIFO that no process is reading"}},
      {"stereo",
       pair + "--export-uai {out}/empty/model.uai --trace {dir}/fifo --labels 8",
       2,
       {"--trace: '", "fifo' is a FIFO that no process is reading"}},
      {"stereo",
       pair + "--gt {dir}/gt-unknown.png --gt-divisor 4",
       2,
       {"GT '", "gt-unknown.png' has no known pixel"}},
      {"stereo",
       pair + "--gt {dir}/gt.png --gt-divisor 4 --mask {dir}/mask-none.png",
       2,
       {"mask '", "mask-none.png' marks no pixel for evaluation"}},
      {"stereo",
       pair + "--gt {dir}/gt.png --gt-divisor 4 --mask {dir}/mask-grey.png",
       2,
       {"mask-grey.png' has the grey value 128 at (0, 0)", "expected only 255 (evaluate)"}},
      {"stereo",
       pair + "--gt {dir}/gt.png --gt-divisor 4 --mask {dir}/mask-red.png",
       2,
       {"mask-red.png' has the grey value 76 at (0, 0)"}},
      {"stereo", pair + "--schedule cp:1", 2, {"--schedule: level 'cp:1': expected cp:N_L,N_iter"}},
      {"stereo",
       pair + "--schedule auto:",
       2,
       {"--schedule: level 'auto:': auto needs at least one fraction"}},
      {"stereo",
       pair + "--schedule \"slic:200 flat\"",
       2,
       {"--schedule: slic:200 flat: level slic:200 needs an image whose shorter side is at "
        "least 200 pixels, and the image is 48x32"}},
      {"stereo",
       pair + "--labels 8 --schedule \"cp:9,1 flat\"",
       2,
       {"--schedule: ", "cp:9,1", "(--labels 8)"}},
      {"stereo",
       pair + "--solver magic",
       2,
       {"--solver: unknown solver 'magic' (expected expansion, swap, lbp or icm)"}},
      {"stereo", pair + "--maxflow fastest", 2, {"--maxflow: unknown max-flow backend 'fastest'"}},
      {"stereo", pair + "--graph-memory -1", 2, {"--graph-memory: expected a finite number in"}},
      {"stereo", pair + "--label-order backwards", 2, {"--label-order: ", "'backwards'"}},
      {"stereo", pair + "--near-radius -1", 2, {"--near-radius: expected an integer in [0, "}},
      {"stereo",
       pair + "--near-radius 2 --near-levels coarse",
       2,
       {"--near-levels: unknown near-move levels 'coarse' (expected original or all)"}},
      {"stereo",
       pair + "--near-levels all --near-radius 0 --shift-moves=off",
       2,
       {"--near-levels: has no effect without --near-radius or --shift-moves"}},
      {"stereo",
       pair + "--solver swap --near-radius 2",
       2,
       {"--near-radius or --label-order with --solver swap: near moves are expansion moves"}},
      {"stereo",
       pair + "--solver icm --near-radius 3",
       2,
       {"--near-radius or --label-order with --solver icm: near moves are expansion moves"}},
      {"stereo", pair + "--shift-moves=maybe", 2, {"--shift-moves: expected on, off or auto"}},
      {"stereo", pair + "--smoothness wavy", 2, {"--smoothness: ", "'wavy'"}},
      {"stereo", pair + "--lab 8", 2, {"unrecognised option '--lab'"}},
      {"stereo", pair + "--bogus", 2, {"unrecognised option '--bogus'"}},
      // Boost's message templates use %option% and friends; found by fuzzing (it never ended).
      {"stereo", pair + "--%option%", 2, {"unrecognised option '--%option%'"}},
      {"stereo", pair + "-%prefix%q", 2, {"unrecognised option '-%prefix%q'"}},
      {"stereo",
       scene + "scenes-good --gt {left}",
       2,
       {"--scene loads the scene's own GT and masks"}},
      {"stereo", "{left} {right} " + scene + "scenes-good", 2, {"--scene replaces LEFT RIGHT"}},
      {"stereo",
       "-o {out}/stereo --scene Nowhere --data {dir}/scenes-good",
       2,
       {"no scene 'Nowhere' in ", "scenes.csv (have: Pair)"}},
      {"stereo",
       scene + "missing-folder",
       2,
       {"scene table '", "missing-folder/scenes.csv' does not exist"}},
      {"stereo",
       scene + "scenes-fifo",
       2,
       {"scene table '", "scenes-fifo/scenes.csv' is not a regular file (a FIFO)"}},
      {"stereo",
       scene + "scenes-zero",
       2,
       {"scene table '", "scenes-zero/scenes.csv' is not a regular file (a device)"}},
      {"stereo",
       scene + "scenes-folder",
       2,
       {"scene table '", "scenes-folder/scenes.csv' is a folder, not a file"}},
      {"stereo",
       scene + "scenes-width",
       2,
       {"scenes-width/scenes.csv' line 2: width: expected an integer in [1, 65536], got '48x'"}},
      {"stereo", scene + "scenes-fields", 2, {"scenes-fields/scenes.csv' line 2: has 5 fields"}},
      {"stereo",
       scene + "scenes-divisor",
       2,
       {"line 2: gt_divisor: expected a finite number > 0, got 'inf'"}},
      {"stereo", scene + "scenes-twice", 2, {"line 3: scene 'Pair' appears twice"}},
      {"stereo", scene + "scenes-nocolumn", 2, {"scenes-nocolumn/scenes.csv': no column 'dir'"}},
      {"stereo",
       "{dir}/big.png {dir}/big.png -o {out}/stereo --labels 256",
       2,
       {"big.png': the TSGO energy of 4000x3000 pixels and 256 labels solved by expansion needs ",
        "more than the run's memory budget of"}},
      {"stereo",
       "{dir}/big.png {dir}/big.png -o {out}/stereo --labels 256 --memory 60000",
       2,
       {"the TSGO energy of 4000x3000 pixels and 256 labels solved by expansion needs ",
        "this machine has available"}},
      {"stereo",
       pair + "--memory 0.01",
       2,
       {"labels solved by expansion needs ",
        "more than the run's memory budget of 10.2 MiB (--memory 0.01)"}},
      {"stereo", pair + "--memory nan", 2, {"--memory: expected a finite number in"}},
      {"stereo", pair + "--labels 8 --max-steps 2 -q --trace /dev/full", 1, {"'/dev/full'"}},
      {"stereo", "{left} {right} -o {left}", 1, {"left.png"}},
  };
}

std::vector<Case> segment_cases() {
  const std::string run = "{image} {seeds} -o {out}/segment ";
  return {
      {"segment",
       "{image} {seeds} -o {out}/stereo",
       1,
       {"the output folder '", "stereo' holds the outputs of c2f-stereo, not of c2f-segment"}},
      {"segment",
       "{image} {out}/segment/labels.png -o {out}/segment",
       2,
       {"SEEDS '", "' is labels.png, a file the run writes into"}},
      {"segment", run + "--trace {seeds}", 2, {"--trace '", "' is the same file as SEEDS '"}},
      {"segment",
       run + "--memory 0.001",
       2,
       {"pixels into ", "more than the run's memory budget of 1.0 MiB (--memory 0.001)"}},
      {"segment",
       "{image} {dir}/seeds-green.png -o {out}/segment --binary",
       2,
       {"seeds-green.png': pixel (30, 12) has the colour (0, 200, 0)",
        "none of red (object), blue (background) and white (unlabelled)"}},
      {"segment",
       "{dir}/missing.png {seeds} -o {out}/segment",
       2,
       {"IMAGE: file '", "missing.png' does not exist"}},
      {"segment",
       "{image} {dir}/missing.png -o {out}/segment",
       2,
       {"SEEDS: file '", "missing.png' does not exist"}},
      {"segment",
       "{image} {seeds} -o {out}/segment --gt {dir}/" + std::string(300, 'g') + ".png",
       2,
       {"--gt: file '", "' cannot be examined (File name too long)"}},
      {"segment", "{image} -o {out}/segment", 2, {"give IMAGE and SEEDS (got 1 positional"}},
      {"segment", run + "{gt}", 2, {"unexpected argument '", "takes at most 2 (IMAGE SEEDS)"}},
      {"segment", "{image} {seeds}", 2, {"-o/--out: an output directory is required"}},
      {"segment",
       "{image} {dir}/small.png -o {out}/segment",
       2,
       {"SEEDS '", "small.png' is 20x20, the image is 40x30"}},
      {"segment",
       "{image} {dir}/seeds-none.png -o {out}/segment",
       2,
       {"seeds-none.png' has 0 seed colour(s) besides white; segmentation needs at least 2"}},
      {"segment",
       "{image} {dir}/seeds-one.png -o {out}/segment",
       2,
       {"seeds-one.png' has 1 seed colour(s)"}},
      {"segment", "{image} {image} -o {out}/segment", 2, {"is it an image rather than seeds?"}},
      {"segment",
       "{image} {dir}/empty.png -o {out}/segment",
       2,
       {"empty.png' could not be read as an image"}},
      {"segment",
       "{dir}/text.png {seeds} -o {out}/segment",
       2,
       {"text.png' could not be read as an image"}},
      {"segment",
       run + "--aux annealing",
       2,
       {"--aux: unknown auxiliary-variable strategy 'annealing'"}},
      {"segment", run + "--method magic", 2, {"--method: ", "'magic'"}},
      {"segment", run + "--start later", 2, {"--start: ", "'later'"}},
      {"segment", run + "--alpha 1", 2, {"--alpha: expected a finite number in [0, 1), got '1'"}},
      {"segment", run + "--lambda -1", 2, {"--lambda: expected a finite number in [0, "}},
      {"segment", run + "--theta nan", 2, {"--theta: ", "got 'nan'"}},
      {"segment", run + "--classes 0", 2, {"--classes: expected an integer in [1, 256], got '0'"}},
      {"segment", run + "--classes 1000", 2, {"--classes: ", "got '1000'"}},
      {"segment",
       run + "--kmeans matlab",
       2,
       {"--kmeans: expected reference or plusplus, got 'matlab'"}},
      {"segment", run + "--downscale 0", 2, {"--downscale: expected an integer in [1, 1024]"}},
      {"segment", run + "--time-limit inf", 2, {"--time-limit: ", "got 'inf'"}},
      {"segment",
       run + "--plateau soon",
       2,
       {"--plateau: expected auto, sweep or a number, got 'soon'"}},
      {"segment", run + "--plateau 0", 2, {"--plateau: expected an integer in [1, "}},
      {"segment", run + "--final-plateau -1", 2, {"--final-plateau: ", "got '-1'"}},
      {"segment",
       run + "--schedule cp:9,1",
       2,
       {"--schedule: level cp:9,1 has N_L 9 above the 3 labels"}},
      {"segment", run + "--schedule local:1,1", 2, {"local grouping reads a pairwise energy"}},
      // The default schedule on an image too small for it (OpenCV's SLIC message before, which
      // named no schedule).
      {"segment",
       run + "--downscale 4",
       2,
       {"--schedule: superpixels (slic:16 slic:8 flat): level slic:16 needs an image whose",
        "the image is 10x7 (choose smaller regions, or --schedule flat)"}},
      {"segment",
       run + "--schedule \"cp:x\"",
       2,
       {"--schedule: level 'cp:x': expected cp:N_L,N_iter"}},
      {"segment", run + "--labels-from-gt", 2, {"--labels-from-gt needs --gt"}},
      {"segment",
       run + "--labels-from-gt --binary --gt {gt}",
       2,
       {"--labels-from-gt and --binary are two conventions"}},
      {"segment",
       run + "--gt {dir}/missing.png",
       2,
       {"--gt: file '", "missing.png' does not exist"}},
      {"segment",
       run + "--gt {dir}/small.png",
       2,
       {"GT '", "small.png' is 20x20, the image is 40x30"}},
      {"segment",
       run + "--gt {dir}/gt-odd.png",
       2,
       {"GT '", "gt-odd.png': colour (30,200,10) at (2, 2) is none of the label colours"}},
      {"segment",
       "{image} {dir}/seeds-binary.png -o {out}/segment --binary --gt {dir}/gt-grey77.png",
       2,
       {"gt-grey77.png': grey level 77 at pixel", "is none of 0 (background), 128"}},
      {"segment", run + "--max-steps x", 2, {"--max-steps: ", "got 'x'"}},
      {"segment", run + "--bogus 3", 2, {"unrecognised option '--bogus'"}},
      {"segment", run + "--gmm-seed -1", 2, {"--gmm-seed: expected an integer in [0, "}},
      {"segment", run + "--edge-seed x", 2, {"--edge-seed: expected an integer in [0, "}},
      {"segment", run + "--x%original_token%", 2, {"unrecognised option '--x%original_token%'"}},
  };
}

std::vector<Case> synthetic_cases() {
  const std::string run = "-o {out}/synthetic ";
  return {
      {"synthetic",
       run + "--width 9223372036854775809",
       2,
       {"--width: expected an integer in [2, 65536], got '9223372036854775809'"}},
      {"synthetic", run + "--width 1", 2, {"--width: expected an integer in [2, 65536]"}},
      {"synthetic", run + "--height abc", 2, {"--height: ", "got 'abc'"}},
      {"synthetic", run + "--labels 1", 2, {"--labels: expected an integer in [2, "}},
      {"synthetic", run + "--noise nan", 2, {"--noise: expected a finite number", "got 'nan'"}},
      {"synthetic", run + "--smoothness -1", 2, {"--smoothness: expected a finite number in [0, "}},
      {"synthetic", run + "--seed -1", 2, {"--seed: expected an integer in [0, "}},
      {"synthetic", run + "--blocks 16,x", 2, {"--blocks: 'x' is not a block size >= 1"}},
      {"synthetic", run + "--%canonical_option%", 2, {"'--%canonical_option%'"}},
      {"synthetic",
       run + "--blocks 16,5",
       2,
       {"--blocks: BlockHierarchy: block size 5 does not divide the previous size 16"}},
      {"synthetic", run + "--plateau 0", 2, {"--plateau: expected an integer in [1, "}},
      {"synthetic", run + "--time-limit -5", 2, {"--time-limit: ", "got '-5'"}},
      {"synthetic",
       run + "extra",
       2,
       {"unexpected argument 'extra': the tool takes no positional arguments"}},
      {"synthetic",
       run + "--width 65536 --height 65536",
       2,
       {"the synthetic problem of 65536x65536 pixels with 16 labels needs ",
        "more than the run's memory budget of"}},
      {"synthetic",
       run + "--width 65536 --height 65536 --memory 60000",
       2,
       {"the synthetic problem of 65536x65536 pixels with 16 labels needs ",
        "this machine has available"}},
      {"synthetic", run + "--memory -2", 2, {"--memory: expected a finite number in [0, "}},
  };
}

}  // namespace

TEST_CASE("every tool refuses malformed input by name and leaves earlier outputs untouched",
          "[cli][malformed]") {
  const Inputs inputs;
  const auto& names = inputs.names;
  // The earlier good runs whose outputs every case must leave as they were.
  for (const auto& [tool, arguments] : std::vector<std::pair<const char*, std::string>>{
           {"stereo", "{left} {right} -o {out}/stereo --labels 8 --max-steps 6 -q"},
           {"segment", "{image} {seeds} --gt {gt} -o {out}/segment --classes 4 --max-steps 4 -q"},
           {"synthetic", "-o {out}/synthetic --width 32 --height 24 --blocks 8,4"}}) {
    const auto r = c2f::test::run_tool(binary(tool), substitute(arguments, names));
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
  }
  auto before = snapshot(inputs.dir / "out");
  const std::string left_before = read_bytes(inputs.dir / "left.png");
  REQUIRE(before.size() >= 15);

  std::vector<Case> cases = stereo_cases();
  for (auto&& more : {segment_cases(), synthetic_cases()})
    cases.insert(cases.end(), more.begin(), more.end());
  CHECK(cases.size() >= 60);
  for (const Case& c : cases) {
    const std::string arguments = substitute(c.arguments, names);
    const auto r = c2f::test::run_tool(binary(c.tool), arguments);
    INFO("c2f-" << c.tool << " " << arguments << "\n" << r.output);
    if (std::getenv("C2F_SHOW_MESSAGES"))
      std::cout << "$ c2f-" << c.tool << " " << arguments << "\n" << r.output;
    CHECK(r.exit_code == c.exit_code);
    CHECK_THAT(r.output, Catch::Contains(std::string("c2f-") + c.tool + ": error: "));
    for (const std::string& part : c.expected) CHECK_THAT(r.output, Catch::Contains(part));
    const auto after = snapshot(inputs.dir / "out");
    CHECK(after == before);
    if (after != before) before = after;  // one failure is reported once
  }
  CHECK(read_bytes(inputs.dir / "left.png") == left_before);
}

TEST_CASE("every tool prints its usage for --help and exits 0", "[cli]") {
  for (const auto& [tool, usage] : std::vector<std::pair<const char*, const char*>>{
           {"stereo", "Usage: c2f-stereo LEFT RIGHT -o OUTDIR"},
           {"segment", "Usage: c2f-segment IMAGE SEEDS -o OUTDIR"},
           {"synthetic", "c2f-synthetic: restores a noisy"}}) {
    const auto r = c2f::test::run_tool(binary(tool), "--help");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.output, Catch::Contains(usage) && Catch::Contains("(an integer in ["));
  }
}
