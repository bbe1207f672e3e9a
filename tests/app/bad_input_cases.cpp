// The bad-input matrix's cases: every kind of bad input a user can type, each with the words
// its one stderr line must contain (tests/app/bad_input_matrix_test.cpp runs them).
#include "bad_input_cases.hpp"

#include <string>
#include <utility>
#include <vector>

namespace collide::bad_input {
namespace {

// A valid two-cart scene file; cases write variants of it.
const std::string kGoodScene = R"(name = "carts"
duration = 4
restitution = 0.5
[[body]]
mass = 1
size = 0.5
position = -2
velocity = 2
[[body]]
mass = 1
size = 0.5
position = 2
velocity = -1
)";

// The good scene plus a third body at x = 6 m whose keys are `mass = 1`, `size = 0.5`,
// `position = 6`, except those that `changes` (e.g. {"mass", "0"}) replaces or adds.
std::string withBody(const std::vector<std::pair<std::string, std::string>>& changes) {
  std::vector<std::pair<std::string, std::string>> keys = {
      {"mass", "1"}, {"size", "0.5"}, {"position", "6"}};
  for (const auto& [key, value] : changes) {
    bool replaced_key = false;
    for (auto& entry : keys) {
      if (entry.first == key) entry.second = value, replaced_key = true;
    }
    if (!replaced_key) keys.emplace_back(key, value);
  }
  std::string text = kGoodScene + "[[body]]\n";
  for (const auto& [key, value] : keys) text += key + " = " + value + "\n";
  return text;
}

// A 2D scene with gravity and one disk hanging from [0, 0] on a 1 m string; `body_keys` are
// appended to the hanging disk's table, `extra` after it.
std::string hangingScene(const std::string& body_keys, const std::string& extra = "",
                         const std::string& gravity = "[0, -9.81]") {
  return "dimensions = 2\nduration = 1\ngravity = " + gravity +
         "\n[[body]]\nname = \"bob\"\nmass = 1\nsize = 0.1\nposition = [0, -1]\n" + body_keys +
         extra;
}

// One body more than a scene may hold (1000), each 1 m wide and 2 m from the next: apart, so
// the count is the only thing wrong.
std::string crowdedScene() {
  std::string text = "duration = 1\n";
  for (int i = 0; i <= 1000; ++i) {
    text += "[[body]]\nmass = 1\nsize = 1\nposition = " + std::to_string(2 * i) + "\n";
  }
  return text;
}

// `count` Cyrillic letters: two bytes each in UTF-8, one character each.
std::string cyrillic(int count) {
  std::string text;
  for (int i = 0; i < count; ++i) text += "\u0436";
  return text;
}

}  // namespace

const std::vector<BadInput>& cases() {
  static const std::vector<BadInput> all = {
      {"MissingSceneFile", "", "render {dir}/nope.toml -o {dir}/x.mp4", {"nope.toml"}},
      {"SceneIsADirectory", "", "render {dir} -o {dir}/x.mp4", {"{dir}"}},
      {"MalformedToml",
       "mass = = 1\n",
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"scene.toml:1:", "malformed TOML"}},
      {"UnknownPreset",
       "",
       "render worked-exampel -o {dir}/x.mp4",
       {"did you mean 'worked-example'"}},
      {"UnknownKey",
       "restitutoin = 0.3\n" + kGoodScene,
       "check {dir}/scene.toml",
       {"restitutoin", "did you mean 'restitution'"}},
      {"WrongType",
       withBody({{"velocity", "\"fast\""}}),
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"scene.toml:", "body.3.velocity", "fast"}},
      {"ZeroMass",
       withBody({{"mass", "0"}}),
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"body.3.mass: 0", "more than 0"}},
      {"NegativeMass",
       withBody({{"mass", "-1"}}),
       "still {dir}/scene.toml --at 1 -o {dir}/x.png",
       {"body.3.mass: -1", "more than 0"}},
      {"RestitutionBelowZero",
       "",
       "render worked-example --set restitution=-0.1 -o {dir}/x.mp4",
       {"restitution", "-0.1", "0 to 1"}},
      {"RestitutionAboveOne",
       "",
       "render worked-example --e 1.5 -o {dir}/x.mp4",
       {"1.5", "0 to 1"}},
      {"NanInFile",
       withBody({{"velocity", "nan"}}),
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"body.3.velocity", "nan"}},
      {"InfInFile",
       "gravity = inf\n" + kGoodScene,
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"scene.toml:1:", "gravity", "inf"}},
      {"NanInSet",
       "",
       "render worked-example --set body.1.mass=nan -o {dir}/x.mp4",
       {"body.1.mass", "nan"}},
      // Beyond the range of a double: a number out of range, echoed as typed, never "a string".
      {"MassBeyondDoubleInSet",
       "",
       "data worked-example --set body.1.mass=1e999 --json {dir}/x.json",
       {"--set body.1.mass=1e999: body.1.mass: 1e999: not a finite number", "more than 0"}},
      {"RestitutionBelowMinusDoubleInSet",
       "",
       "still worked-example --set restitution=-1e400 -o {dir}/x.png",
       {"restitution: -1e400: not a finite number", "from 0 to 1"}},
      {"MassUnderflowingInSet",
       "",
       "data worked-example --set body.2.mass=1e-999 --csv {dir}/x.csv",
       {"body.2.mass: 1e-999: out of range", "more than 0"}},
      // The changed dimensions are the cause, not the 1D preset's gravity (nor a 2D one's y).
      {"DimensionsChangedInSet",
       "",
       "render worked-example --set dimensions=2 -o {dir}/x.mp4",
       {"--set dimensions=2: dimensions: 2: preset worked-example is written for 1D",
        "allowed: 1, or a scene written for 2D"}},
      {"DimensionsChangedInSet2D",
       "",
       "data billiards-glancing --set dimensions=1 --json {dir}/x.json",
       {"--set dimensions=1: dimensions: 1: preset billiards-glancing is written for 2D"}},
      {"InfDuration",
       "",
       "render worked-example --duration inf -o {dir}/x.mp4",
       {"--duration", "inf"}},
      {"OverlappingBodies",
       withBody({{"position", "2.2"}}),
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"overlap"}},
      {"ZeroDuration",
       "",
       "render worked-example --duration 0 -o {dir}/x.mp4",
       {"--duration", "more than 0"}},
      {"NegativeDurationInFile",
       "duration = -3\n[[body]]\nmass = 1\nsize = 1\nposition = 0\n",
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"scene.toml:1:", "duration: -3"}},
      {"AbsurdDuration",
       "",
       "render worked-example --duration 100000 -o {dir}/x.mp4",
       {"--duration", "3600"}},
      {"AbsurdFps", "", "render worked-example --fps 100000 -o {dir}/x.mp4", {"--fps", "240"}},
      {"AbsurdBodyCount",
       crowdedScene(),
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"scene.toml:", "1001 bodies", "at most 1000"}},
      {"AbsurdResolution",
       "",
       "render worked-example --size 7682x4320 -o {dir}/x.mp4",
       {"--size", "7680x4320"}},
      {"BadSetExpression",
       "",
       "render worked-example --set restitution -o {dir}/x.mp4",
       {"--set", "KEY=VALUE"}},
      {"SetUnknownKey",
       "",
       "render worked-example --set body.2.mas=3 -o {dir}/x.mp4",
       {"body.2.mas", "mass"}},
      {"UnknownOutputExtension", "", "render worked-example -o {dir}/x.avi", {"x.avi", "allowed"}},
      {"OutputInMissingDirectory",
       "",
       "render worked-example -o {dir}/missing/x.mp4",
       {"does not exist"}},
      {"StillNotPng", "", "still worked-example --at 1 -o {dir}/x.jpg", {"x.jpg", ".png"}},
      {"UnknownBackend",
       "",
       "render worked-example --backend vulkan -o {dir}/x.mp4",
       {"--backend", "osmesa"}},
      // Outputs (issue 14): only a regular file or a new name is replaced; the rest is refused
      // before anything runs, naming what the user typed and never a temporary file.
      {"JsonIntoADirectory",
       "",
       "data worked-example --json {dir}/d",
       {"--json", "{dir}/d", "is a directory"},
       "mkdir d"},
      {"CsvIntoADirectory",
       "",
       "data worked-example --csv {dir}/d --json {dir}/x.json",
       {"--csv", "{dir}/d", "is a directory"},
       "mkdir d && echo earlier > x.json"},
      {"FramesIntoARegularFile",
       "",
       "render worked-example -o {dir}/fr/",
       {"-o", "fr/", "not a directory"},
       "echo earlier > fr"},
      {"VideoIntoADirectoryNamedLikeAVideo",
       "",
       "render worked-example -o {dir}/x.mp4",
       {"x.mp4", "is a directory", "--format frames"},
       "mkdir x.mp4"},
      {"FormatDisagreesWithExtension",
       "",
       "render worked-example --format gif -o {dir}/x.mp4",
       {"--format", "gif", "x.mp4", ".mp4"},
       "echo earlier > x.mp4"},
      {"FramesFormatOnAVideoName",
       "",
       "render worked-example --format frames -o {dir}/x.webm",
       {"--format", "frames", ".webm"}},
      {"VideoToStdoutWithoutFormat", "", "render worked-example -o -", {"-o", "'-'", "--format"}},
      {"FramesToStdout",
       "",
       "render worked-example --format frames -o -",
       {"PNG frames", "stdout"}},
      {"CaptionsBesideStdout",
       "",
       "render worked-example --format mp4 -o - --captions",
       {"--captions", "--embed-captions"}},
      {"SubRipBesideAFifo",
       "",
       "render worked-example -o {dir}/pipe --srt",
       {"--srt", "pipe"},
       "mkfifo pipe"},
      {"OutputIsALinkLoop",
       "",
       "data worked-example --json {dir}/loop.json",
       {"--json", "loop.json", "link loop"},
       "ln -s loop.json loop.json"},
      {"OutputLinkIntoAMissingDirectory",
       "",
       "data worked-example --json {dir}/dangling.json",
       {"--json", "dangling.json", "missing directory"},
       "ln -s missing/x.json dangling.json"},
      // Inputs (issue 14): one bounded reader; devices refused before reading.
      {"SceneIsTheZeroDevice",
       "",
       "check {dir}/zero",
       {"{dir}/zero", "character device"},
       "mknod zero c 1 5 || exit 77"},
      {"SceneIsTheRandomDevice",
       "",
       "render {dir}/urandom -o {dir}/x.mp4",
       {"{dir}/urandom", "character device"},
       "mknod urandom c 1 9 || exit 77"},
      {"SceneFileTooLarge",
       "",
       "check {dir}/big.toml",
       {"big.toml", "4 MiB"},
       "yes '# comment' | head -c 4194305 > big.toml"},
      // Options (issue 14): every numeric option checked like a scene value, echoed as typed.
      {"QualityMinusOne",
       "",
       "render worked-example --quality -1 -o {dir}/x.mp4",
       {"--quality: -1", "0 to 51"}},
      {"QualityOnAGif",
       "",
       "render worked-example --quality 20 -o {dir}/x.gif",
       {"--quality", "GIF"}},
      {"CsvStepNan",
       "",
       "data worked-example --csv {dir}/x.csv --dt nan",
       {"--dt: nan", "0.0005 to 0.05"}},
      {"CsvStepInf", "", "data worked-example --csv {dir}/x.csv --dt inf", {"--dt: inf"}},
      {"CsvStepTooLarge",
       "",
       "data worked-example --csv {dir}/x.csv --dt 1",
       {"--dt: 1:", "0.0005 to 0.05"},
       "echo earlier > x.csv"},
      {"DataVersionUnknown",
       "",
       "data worked-example --csv {dir}/x.csv --data-version 3",
       {"--data-version: 3:", "1 or 2"},
       "echo earlier > x.csv"},
      {"GifFasterThanItsDelays",
       "",
       "render worked-example --fps 120 -o {dir}/x.gif",
       {"--fps: 120", "GIF", "1 to 50"}},
      {"GifAtSixtyFps",
       "",
       "render worked-example --format gif --fps 60 -o {dir}/x",
       {"--fps: 60", "hundredths"}},
      {"StillJustPastTheEnd",
       "",
       "still worked-example --at 4.0000001 -o {dir}/x.png",
       {"--at: 4.0000001:", "0 to 4 s"}},
      {"StillBeforeTheStart", "", "still worked-example --at -1 -o {dir}/x.png", {"--at: -1:"}},
      {"StillAtNan", "", "still worked-example --at nan -o {dir}/x.png", {"--at: nan"}},
      {"StrobeRateZero",
       "",
       "strobe worked-example --rate 0 -o {dir}/x.png",
       {"--rate: 0:", "0.1 to 1000"}},
      {"StrobeRateFromTheScene",
       kGoodScene + "[view]\nstrobe_rate = 900\n",
       "strobe {dir}/scene.toml -o {dir}/x.png",
       {"view.strobe_rate: 900", "2000 images"}},
      {"FpsZero", "", "render worked-example --fps 0 -o {dir}/x.mp4", {"--fps", "0"}},
      {"SizeWithLetters",
       "",
       "render worked-example --size 12ax90 -o {dir}/x.mp4",
       {"--size", "12ax90"}},
      {"TransparentMp4",
       "",
       "render worked-example --transparent -o {dir}/x.mp4",
       {"--transparent", "alpha"}},
      {"SoundOnAGif", "", "render worked-example --sound -o {dir}/x.gif", {"--sound", "GIF"}},
      {"EmbeddedCaptionsInFrames",
       "",
       "render worked-example --embed-captions -o {dir}/fr/",
       {"--embed-captions"}},
      {"BatchSweepValueOutOfRange",
       "",
       "batch worked-example -o {dir}/b --sweep restitution=0.5,1.5 --formats json",
       {"restitution", "1.5", "0 to 1"}},
      {"BatchFileSceneWithBadSweep",
       kGoodScene,
       "batch {dir}/scene.toml -o {dir}/b --sweep body.1.mass=1,-2 --formats csv",
       {"body.1.mass", "-2"}},
      // Messages (issue 14): the command, the key and the value as typed, in one line.
      {"UnknownCommand",
       "",
       "rendr worked-example -o {dir}/x.mp4",
       {"'rendr': unknown command", "did you mean 'render'"}},
      {"UnknownCommandFarFromAny", "", "paint worked-example", {"'paint'", "allowed: render"}},
      {"SetValueWithANewline",
       "",
       "render worked-example --set \"body.1.mass=$(printf '1\\n2')\" -o {dir}/x.mp4",
       {"body.1.mass", "\\n"}},
      {"HugeUnknownKeyInAFile",
       std::string(1 << 20, 'k') + " = 1\n" + kGoodScene,
       "check {dir}/scene.toml",
       {"kkkkkkkkkk...", "unknown key"}},
      // 100 000 characters typed as a --set key: quoted cut at 80 characters, both in the
      // expression and as the key.
      {"HugeUnknownKeyInSet",
       "",
       "check worked-example --set " + std::string(100000, 'k') + "=1",
       {"--set " + std::string(80, 'k') + "...: " + std::string(80, 'k') + "...: 1: unknown key"}},
      // A frame name in the frames directory that no output may replace: refused before any
      // frame is drawn, and nothing else in the directory changes.
      {"FrameNameIsADirectory",
       "",
       "render worked-example --duration 0.2 --size 64x64 -o {dir}/fr/",
       {"fr/frame_00001.png': is a directory"},
       "mkdir -p fr/frame_00001.png && echo earlier > fr/frame_00000.png"},
      {"LongCyrillicBodyName",
       "",
       "check worked-example --set body.1.name=" + cyrillic(65),
       {"body.1.name", "at most 64 characters"}},
      {"JsonLinkToADirectory",
       "",
       "data worked-example --json {dir}/l.json",
       {"--json", "l.json", "is a directory"},
       "mkdir d2 && ln -s d2 l.json"},
      {"PivotInsideTheBody",
       hangingScene("pivot = [0.05, -1]\n"),
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"body.1.pivot", "[0.05, -1]", "inside the body", "allowed:"}},
      {"PivotOnAnotherBody",
       hangingScene("pivot = [2, 0]\n",
                    "[[body]]\nname = \"rock\"\nmass = 1\nsize = 0.3\nposition = [2, 0.1]\n"),
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"body.1.pivot", "on body 2 ('rock')", "allowed: a pivot clear of every body"}},
      {"ZeroStringLength",
       "dimensions = 2\ngravity = [0, -9.81]\n[[body]]\nmass = 1\nsize = 0.1\n"
       "pivot = [0, 0]\nlength = 0\n",
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"body.1.length: 0: out of range", "a string length in m, more than 0 and"}},
      {"NegativeStringLength",
       "dimensions = 2\ngravity = [0, -9.81]\n[[body]]\nmass = 1\nsize = 0.1\n"
       "pivot = [0, 0]\nlength = -2\nangle = 30\n",
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"body.1.length: -2: out of range", "allowed: a string length in m, more than 0 and"}},
      {"PivotInA1DScene",
       withBody({{"pivot", "[6, 1]"}}),
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"body.3.pivot", "only in 2D scenes"}},
      {"StringCrossesAWallAtTheStart",
       hangingScene("pivot = [0, 0]\n",
                    "[[wall]]\nname = \"shelf\"\nposition = [0, -0.5]\nnormal = [0, -1]\n"),
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"body.1.pivot", "crosses wall 'shelf'", "allowed: a pivot on the free side"}},
      {"StringWithoutGravity",
       hangingScene("pivot = [0, 0]\n", "", "[0, 0]"),
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"body.1.pivot", "gravity pulling down", "allowed:"}},
      {"LengthWithoutPivot",
       hangingScene("length = 1\n"),
       "render {dir}/scene.toml -o {dir}/x.mp4",
       {"body.1.length", "needs a pivot"}},
      {"StillIntoADirectoryNamedPng",
       "",
       "still worked-example --at 1 -o {dir}/x.png",
       {"-o", "x.png", "is a directory"},
       "mkdir x.png"},
      // collide layout: one frame or every frame, never both; the frame inside the run.
      {"LayoutAtAndFps",
       "",
       "layout worked-example --at 1 --fps 30 --json {dir}/x.json",
       {"--at: 1", "--fps", "allowed: one frame (--at) or every frame (--fps)"}},
      {"LayoutPastTheEnd",
       "",
       "layout worked-example --at 4.5 --json {dir}/x.json",
       {"--at: 4.5:", "0 to 4 s"}},
      {"LayoutFpsZero", "", "layout worked-example --fps 0 --json {dir}/x.json", {"--fps: 0"}},
      {"LayoutIntoADirectory",
       "",
       "layout worked-example --at 1 --json {dir}/d",
       {"--json", "{dir}/d", "is a directory"},
       "mkdir d"},
  };
  return all;
}

}  // namespace collide::bad_input
