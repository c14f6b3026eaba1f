#include "tessera/io/stage_world.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "internal/decoders.hpp"
#include "internal/file_util.hpp"
#include "internal/raw_image.hpp"
#include "tessera/core/angle.hpp"

namespace tessera {
namespace {

// --- Stage worldfile tokens and blocks (Stage libstage/worldfile.cc syntax) ---

struct Token {
  enum Kind { kWord, kString, kOpen, kClose, kOpenList, kCloseList } kind;
  std::string text;
  int line;
};

struct Property {
  std::vector<std::string> values;  // one for `key value`, any number for `key [ ... ]`
  int line = 0;
};

struct Block {
  std::string type;  // for a define: the parent type
  int line = 0;
  std::map<std::string, Property> properties;
};

struct WorldFile {
  std::vector<Block> models;                 // top-level model instances, in file order
  std::map<std::string, Block> definitions;  // define name parent ( ... )
};

Result<std::vector<Token>> tokenize(std::string_view text, const std::string& name) {
  std::vector<Token> tokens;
  int line = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (c == '(' || c == ')' || c == '[' || c == ']') {
      const Token::Kind kind = c == '('   ? Token::kOpen
                               : c == ')' ? Token::kClose
                               : c == '[' ? Token::kOpenList
                                          : Token::kCloseList;
      tokens.push_back({kind, std::string(1, c), line});
      ++i;
    } else if (c == '"') {
      const std::size_t end = text.find('"', i + 1);
      if (end == std::string_view::npos ||
          text.substr(i + 1, end - i - 1).find('\n') != std::string_view::npos) {
        return input_error(name + ":" + std::to_string(line) +
                           ": syntax error: string is not closed on its line");
      }
      tokens.push_back({Token::kString, std::string(text.substr(i + 1, end - i - 1)), line});
      i = end + 1;
    } else {
      const std::size_t start = i;
      while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])) &&
             text[i] != '#' && text[i] != '(' && text[i] != ')' && text[i] != '[' &&
             text[i] != ']' && text[i] != '"') {
        ++i;
      }
      tokens.push_back({Token::kWord, std::string(text.substr(start, i - start)), line});
    }
  }
  return tokens;
}

class Parser {
 public:
  Parser(const std::vector<Token>& tokens, const std::string& name)
      : tokens_(tokens), name_(name) {}

  Result<WorldFile> parse() {
    WorldFile world;
    while (pos_ < tokens_.size()) {
      const Token& t = tokens_[pos_];
      if (t.kind != Token::kWord) return unexpected(t, "a keyword or model type");
      if (t.text == "include") {
        ++pos_;
        if (pos_ >= tokens_.size() || tokens_[pos_].kind != Token::kString) {
          return error(t.line, "syntax error: include needs a quoted file name");
        }
        ++pos_;  // included files are not read: the floorplan's bitmap lives in the .world
      } else if (t.text == "define") {
        if (pos_ + 3 >= tokens_.size() || tokens_[pos_ + 1].kind != Token::kWord ||
            tokens_[pos_ + 2].kind != Token::kWord || tokens_[pos_ + 3].kind != Token::kOpen) {
          return error(t.line, "syntax error: expected 'define <name> <parent> ( ... )'");
        }
        const std::string defined = tokens_[pos_ + 1].text;
        Block block{tokens_[pos_ + 2].text, t.line, {}};
        pos_ += 4;
        if (Status s = body(block, tokens_[pos_ - 1].line); !s) return s.error();
        world.definitions[defined] = std::move(block);
      } else if (pos_ + 1 < tokens_.size() && tokens_[pos_ + 1].kind == Token::kOpen) {
        Block block{t.text, t.line, {}};
        pos_ += 2;
        if (Status s = body(block, t.line); !s) return s.error();
        world.models.push_back(std::move(block));
      } else {
        ++pos_;
        Property ignored;
        if (Status s = value(t, ignored); !s) return s.error();
      }
    }
    return world;
  }

 private:
  // Properties up to the matching ')'. Nested model blocks (sensors on a robot) are skipped.
  Status body(Block& block, int open_line) {
    while (true) {
      if (pos_ >= tokens_.size()) {
        return error(open_line, "syntax error: '(' is never closed");
      }
      const Token& t = tokens_[pos_];
      if (t.kind == Token::kClose) {
        ++pos_;
        return Ok{};
      }
      if (t.kind != Token::kWord) return unexpected(t, "a property name or ')'");
      ++pos_;
      if (pos_ < tokens_.size() && tokens_[pos_].kind == Token::kOpen) {
        ++pos_;
        Block child;
        if (Status s = body(child, t.line); !s) return s;
        continue;
      }
      Property p;
      if (Status s = value(t, p); !s) return s;
      block.properties[t.text] = std::move(p);
    }
  }

  // The value after key `key`: a word, a string or a [ list ].
  Status value(const Token& key, Property& p) {
    p.line = key.line;
    if (pos_ >= tokens_.size())
      return error(key.line, "syntax error: '" + key.text + "' has no value");
    const Token& t = tokens_[pos_];
    if (t.kind == Token::kWord || t.kind == Token::kString) {
      p.values.push_back(t.text);
      ++pos_;
      return Ok{};
    }
    if (t.kind != Token::kOpenList) return unexpected(t, "a value for '" + key.text + "'");
    ++pos_;
    while (true) {
      if (pos_ >= tokens_.size()) return error(t.line, "syntax error: '[' is never closed");
      const Token& v = tokens_[pos_++];
      if (v.kind == Token::kCloseList) return Ok{};
      if (v.kind != Token::kWord && v.kind != Token::kString) {
        return unexpected(v, "a value or ']' in the list for '" + key.text + "'");
      }
      p.values.push_back(v.text);
    }
  }

  [[nodiscard]] Error error(int line, const std::string& what) const {
    return input_error(name_ + ":" + std::to_string(line) + ": " + what);
  }
  [[nodiscard]] Error unexpected(const Token& t, const std::string& expected) const {
    return error(t.line, "syntax error: unexpected '" + t.text + "', expected " + expected);
  }

  const std::vector<Token>& tokens_;
  const std::string& name_;
  std::size_t pos_ = 0;
};

// A property of `model`, else of the define chain of its type.
const Property* find_property(const WorldFile& world, const Block& model, const std::string& key) {
  const Block* block = &model;
  for (int depth = 0; depth < 64 && block != nullptr; ++depth) {
    if (const auto it = block->properties.find(key); it != block->properties.end()) {
      return &it->second;
    }
    const auto def = world.definitions.find(block->type);
    block = def == world.definitions.end() ? nullptr : &def->second;
  }
  return nullptr;
}

bool type_chain_has(const WorldFile& world, const Block& model, std::string_view wanted) {
  std::string type = model.type;
  for (int depth = 0; depth < 64; ++depth) {
    if (type == wanted) return true;
    const auto def = world.definitions.find(type);
    if (def == world.definitions.end()) return false;
    type = def->second.type;
  }
  return false;
}

}  // namespace

Result<StageFloorplan> parse_stage_world(const std::filesystem::path& path) {
  Result<std::string> text = io_internal::read_file_bytes(path);
  if (!text) return text.error();
  return io_internal::decode_stage_world(*text, path);
}

namespace io_internal {

Result<StageFloorplan> decode_stage_world(std::string_view text,
                                          const std::filesystem::path& path) {
  const std::string name = path.string();
  Result<std::vector<Token>> tokens = tokenize(text, name);
  if (!tokens) return tokens.error();
  Result<WorldFile> world = Parser(*tokens, name).parse();
  if (!world) return world.error();

  const Block* chosen = nullptr;
  for (const Block& model : world->models) {
    if (find_property(*world, model, "bitmap") == nullptr) continue;
    const bool floorplan =
        type_chain_has(*world, model, "floorplan") || type_chain_has(*world, model, "map");
    if (chosen == nullptr || (floorplan && !type_chain_has(*world, *chosen, "floorplan") &&
                              !type_chain_has(*world, *chosen, "map"))) {
      chosen = &model;
    }
  }
  if (chosen == nullptr) {
    return input_error(name +
                       ": no model with a bitmap (expected a floorplan block with "
                       "bitmap \"file.png\" and size [w h z])");
  }
  const auto at = [&name](int line, const std::string& what) {
    return input_error(name + ":" + std::to_string(line) + ": " + what);
  };
  StageFloorplan plan;
  plan.line = chosen->line;

  const Property* size = find_property(*world, *chosen, "size");
  if (size == nullptr) {
    return at(chosen->line, "the " + chosen->type + " block with the bitmap has no size [w h z]");
  }
  double w = 0.0, h = 0.0;
  if (size->values.size() < 2 || !io_internal::parse_double(size->values[0], w) ||
      !io_internal::parse_double(size->values[1], h) || !(w > 0.0) || !(h > 0.0)) {
    std::string got;
    for (const auto& v : size->values) got += (got.empty() ? "" : " ") + v;
    return at(size->line, "size must be [w h z] with w, h > 0 metres, got [" + got + "]");
  }
  plan.size_m = {w, h};

  if (const Property* pose = find_property(*world, *chosen, "pose")) {
    // Stage 4: [x y z a]; Stage 3: [x y a]. a is in degrees.
    double v[4] = {0.0, 0.0, 0.0, 0.0};
    const std::size_t n = pose->values.size();
    bool ok = n == 3 || n == 4;
    for (std::size_t i = 0; ok && i < n; ++i) ok = io_internal::parse_double(pose->values[i], v[i]);
    if (!ok) return at(pose->line, "pose must be [x y z a] (metres, degrees)");
    plan.center_m = {v[0], v[1]};
    plan.yaw_rad = deg_to_rad(n == 4 ? v[3] : v[2]);
  }

  const Property* bitmap = find_property(*world, *chosen, "bitmap");
  if (bitmap->values.size() != 1 || bitmap->values[0].empty()) {
    return at(bitmap->line, "bitmap must be one file name");
  }
  const std::filesystem::path file = bitmap->values[0];
  const std::filesystem::path relative = file.is_absolute() ? file : path.parent_path() / file;
  const std::filesystem::path beside = path.parent_path() / file.filename();
  std::error_code ec;
  if (std::filesystem::is_regular_file(relative, ec)) {
    plan.bitmap = relative;
  } else if (std::filesystem::is_regular_file(beside, ec)) {
    plan.bitmap = beside;  // copied out of its bitmaps/ folder, as in collected datasets
  } else {
    return at(bitmap->line, "bitmap '" + bitmap->values[0] + "' not found (looked for " +
                                relative.string() +
                                (beside == relative ? "" : " and " + beside.string()) + ")");
  }
  return plan;
}

}  // namespace io_internal

Result<OccupancyGrid> read_stage_world(const std::filesystem::path& path) {
  Result<StageFloorplan> plan = parse_stage_world(path);
  if (!plan) return plan.error();
  const double yaw_deg = rad_to_deg(plan->yaw_rad);
  const double quarter_turns = std::round(yaw_deg / 90.0);
  if (std::abs(yaw_deg - 90.0 * quarter_turns) > 1e-6) {
    return input_error(path.string() + ":" + std::to_string(plan->line) + ": floorplan pose yaw " +
                       io_internal::format_double(std::round(yaw_deg * 1e6) / 1e6) +
                       " degrees is not supported (only multiples of 90)");
  }
  const int turns = ((static_cast<int>(quarter_turns) % 4) + 4) % 4;

  Result<io_internal::RawImage> image = io_internal::read_raw_image(plan->bitmap);
  if (!image) return image.error();
  const int px_w = image->width, px_h = image->height;
  // Stage has no unknown: anything map_server would not call free is an obstacle.
  std::vector<std::uint8_t> blocked(image->rgb_sum.size());
  const io_internal::PixelRules rules;  // trinary, 0.65 / 0.196
  for (std::size_t i = 0; i < blocked.size(); ++i) {
    blocked[i] = io_internal::map_cell_value(*image, i, rules) != 0 ? 1 : 0;
  }

  // Isotropic resampling: cell size = the finer of the two pixel sizes; a cell is blocked when
  // any pixel it overlaps is (walls never open up).
  const double sx = plan->size_m.x / px_w, sy = plan->size_m.y / px_h;
  const double res = std::min(sx, sy);
  constexpr double kEps = 1e-9;
  const int w = std::max(1, static_cast<int>(std::ceil(plan->size_m.x / res - kEps)));
  const int h = std::max(1, static_cast<int>(std::ceil(plan->size_m.y / res - kEps)));
  if (static_cast<double>(w) * h > static_cast<double>(io_internal::kMaxCells)) {
    return input_error(path.string() + ":" + std::to_string(plan->line) + ": size [" +
                       io_internal::format_double(plan->size_m.x) + " " +
                       io_internal::format_double(plan->size_m.y) + "] over a " +
                       std::to_string(px_w) + " x " + std::to_string(px_h) +
                       " px bitmap needs a grid that is too large");
  }
  const auto span = [&](int i, double pixel_m, int pixels) {
    int lo = static_cast<int>(std::floor(i * res / pixel_m + kEps));
    int hi = static_cast<int>(std::ceil((i + 1) * res / pixel_m - kEps)) - 1;
    lo = std::clamp(lo, 0, pixels - 1);
    hi = std::clamp(std::max(hi, lo), 0, pixels - 1);
    return std::pair<int, int>{lo, hi};
  };
  std::vector<std::uint8_t> model(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  for (int j = 0; j < h; ++j) {
    const auto [k0, k1] = span(j, sy, px_h);  // pixel rows counted from the bottom
    for (int i = 0; i < w; ++i) {
      const auto [c0, c1] = span(i, sx, px_w);
      bool any = false;
      for (int k = k0; k <= k1 && !any; ++k) {
        const std::size_t row = static_cast<std::size_t>(px_h - 1 - k);
        for (int c = c0; c <= c1 && !any; ++c) {
          any = blocked[row * static_cast<std::size_t>(px_w) + static_cast<std::size_t>(c)] != 0;
        }
      }
      model[static_cast<std::size_t>(j) * static_cast<std::size_t>(w) +
            static_cast<std::size_t>(i)] = any ? 1 : 0;
    }
  }

  // Rotate by quarter turns about the centre (counter-clockwise, Stage's positive yaw).
  const bool swapped = turns % 2 == 1;
  const int gw = swapped ? h : w, gh = swapped ? w : h;
  const Vec2 extent = swapped ? Vec2{plan->size_m.y, plan->size_m.x} : plan->size_m;
  const Vec2 origin = plan->center_m - extent * 0.5;
  OccupancyGrid grid(GridGeometry(origin, res, gw, gh));
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      Cell c{i, j};
      if (turns == 1) c = {h - 1 - j, i};
      if (turns == 2) c = {w - 1 - i, h - 1 - j};
      if (turns == 3) c = {j, w - 1 - i};
      grid.set_probability(c, model[static_cast<std::size_t>(j) * static_cast<std::size_t>(w) +
                                    static_cast<std::size_t>(i)]
                                  ? 1.0
                                  : 0.0);
    }
  }
  return grid;
}

}  // namespace tessera
