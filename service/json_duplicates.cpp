#include "json_duplicates.hpp"

#include <nlohmann/json.hpp>
#include <set>
#include <vector>

namespace fosls::service {

namespace {

/// SAX pass that stops at the first repeated key, tracking where it is.
class DuplicateKeyFinder : public nlohmann::json_sax<nlohmann::json> {
 public:
  std::optional<std::string> duplicate;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    levels_.push_back({true, {}, {}, 0});
    return true;
  }
  bool key(string_t& k) override {
    Level& level = levels_.back();
    if (!level.keys.insert(k).second) {
      nlohmann::json::json_pointer pointer = path_of_parents();
      pointer.push_back(k);
      duplicate = pointer.to_string();  // escapes ~ and /
      return false;
    }
    level.key = k;
    return true;
  }
  bool end_object() override {
    levels_.pop_back();
    return value();
  }
  bool start_array(std::size_t) override {
    levels_.push_back({false, {}, {}, 0});
    return true;
  }
  bool end_array() override {
    levels_.pop_back();
    return value();
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;
  }

 private:
  struct Level {
    bool object = true;
    std::set<std::string> keys;
    std::string key;        ///< object: the member being read
    std::size_t index = 0;  ///< array: the element being read
  };

  /// A value ended: the next one in an array has the next index.
  bool value() {
    if (!levels_.empty() && !levels_.back().object) ++levels_.back().index;
    return true;
  }

  /// The pointer of the object being read (all levels but the innermost one's key).
  nlohmann::json::json_pointer path_of_parents() const {
    nlohmann::json::json_pointer p;
    for (std::size_t i = 0; i + 1 < levels_.size(); ++i)
      p.push_back(levels_[i].object ? levels_[i].key : std::to_string(levels_[i].index));
    return p;
  }

  std::vector<Level> levels_;
};

}  // namespace

std::optional<std::string> first_duplicate_key(std::string_view json_text) {
  DuplicateKeyFinder finder;
  nlohmann::json::sax_parse(json_text.begin(), json_text.end(), &finder,
                            nlohmann::json::input_format_t::json, false);
  return finder.duplicate;
}

}  // namespace fosls::service
