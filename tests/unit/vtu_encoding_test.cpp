// The VTU file's binary form holds the values of its ASCII form (decoded here as VTK does: base64
// of a UInt32 byte count and the little-endian values), in the types docs/result-format.md
// names; and the nodal stresses are the area-weighted vertex values, exact for a uniform stress.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../uniaxial_case.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"

namespace fosls {
namespace {

using nlohmann::json;

std::vector<std::uint8_t> base64_decode(const std::string& text) {
  static const std::string alphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<std::uint8_t> out;
  std::uint32_t buffer = 0;
  int bits = 0;
  for (char c : text) {
    const auto k = alphabet.find(c);
    if (k == std::string::npos) continue;  // '=', whitespace
    buffer = (buffer << 6) | static_cast<std::uint32_t>(k);
    if ((bits += 6) >= 8) out.push_back(static_cast<std::uint8_t>(buffer >> (bits -= 8)));
  }
  return out;
}

template <class T>
std::vector<double> as_doubles(const std::vector<std::uint8_t>& bytes) {
  std::uint32_t size = 0;
  std::memcpy(&size, bytes.data(), 4);
  EXPECT_EQ(size + 4, bytes.size());
  std::vector<double> values(size / sizeof(T));
  for (std::size_t i = 0; i < values.size(); ++i) {
    T v;
    std::memcpy(&v, bytes.data() + 4 + i * sizeof(T), sizeof(T));
    values[i] = static_cast<double>(v);
  }
  return values;
}

struct Array {
  std::string type;
  std::vector<double> values;
};

/// Every named DataArray of a VTU text (the points under "points").
std::map<std::string, Array> arrays(const std::string& vtu) {
  static const std::regex element(
      R"re(<DataArray type="(\w+)"([^>]*) format="(\w+)">\n([^<]*)</DataArray>)re");
  std::map<std::string, Array> out;
  for (auto it = std::sregex_iterator(vtu.begin(), vtu.end(), element);
       it != std::sregex_iterator(); ++it) {
    const std::string type = (*it)[1], attributes = (*it)[2], format = (*it)[3], body = (*it)[4];
    std::smatch name;
    static const std::regex name_attribute(R"re(Name="(\w+)")re");
    const std::string key =
        std::regex_search(attributes, name, name_attribute) ? name[1].str() : "points";
    Array a{type, {}};
    if (format == "ascii") {
      std::istringstream in(body);
      for (double v; in >> v;) a.values.push_back(v);
    } else {
      const auto bytes = base64_decode(body);
      if (type == "Float64") a.values = as_doubles<double>(bytes);
      if (type == "Float32") a.values = as_doubles<float>(bytes);
      if (type == "Int32") a.values = as_doubles<std::int32_t>(bytes);
      if (type == "UInt8") a.values = as_doubles<std::uint8_t>(bytes);
    }
    out[key] = a;
  }
  return out;
}

std::string vtu(const json& j, bool ascii) {
  RunControl control;
  control.vtu_ascii = ascii;
  return run_case(*read_case(j).spec, control).vtu;
}

TEST(VtuEncoding, BinaryHoldsTheAsciiValuesInTheDocumentedTypes) {
  json j = testing::uniaxial_case();
  j["mesh"] = {{"builtin", "hertz"}, {"size", 0.2}, {"refinements", 1}};
  j["boundary"] = {{"top", {{"type", "dirichlet"}, {"displacement", {0, -0.01}}}},
                   {"contact",
                    {{"type", "contact"},
                     {"obstacle", {{"type", "plane"}, {"point", {0, 0}}, {"normal", {0, 1}}}}}}};
  const std::string binary = vtu(j, false), ascii = vtu(j, true);
  EXPECT_EQ(binary.find("format=\"ascii\""), std::string::npos);
  EXPECT_EQ(ascii.find("format=\"binary\""), std::string::npos);
  EXPECT_LT(binary.size(), ascii.size());
  const auto b = arrays(binary), a = arrays(ascii);
  ASSERT_EQ(b.size(), a.size());
  const std::map<std::string, std::string> types = {{"points", "Float64"},
                                                    {"u", "Float64"},
                                                    {"contact_pressure", "Float64"},
                                                    {"gap", "Float64"},
                                                    {"sigma", "Float32"},
                                                    {"sigma_nodal", "Float32"},
                                                    {"von_mises", "Float32"},
                                                    {"functional", "Float32"},
                                                    {"contact_boundary", "UInt8"},
                                                    {"generation", "Int32"},
                                                    {"connectivity", "Int32"},
                                                    {"offsets", "Int32"},
                                                    {"types", "UInt8"},
                                                    {"von_mises_nodal", "Float32"}};
  for (const auto& [name, array] : b) {
    ASSERT_TRUE(a.count(name)) << name;
    if (types.count(name)) EXPECT_EQ(array.type, types.at(name)) << name;
    const auto& text = a.at(name).values;
    ASSERT_EQ(array.values.size(), text.size()) << name;
    double scale = 0.0;
    for (double v : text) scale = std::max(scale, std::abs(v));
    // ASCII has 12 digits; Float32 about 7.
    const double tolerance = (array.type == "Float32" ? 1e-6 : 1e-11) * std::max(scale, 1e-300);
    for (std::size_t i = 0; i < text.size(); ++i)
      ASSERT_NEAR(array.values[i], text[i], tolerance) << name << "[" << i << "]";
  }
}

TEST(VtuEncoding, NodalStressesOfAUniformStressAreThatStress) {
  const auto a = arrays(vtu(testing::uniaxial_case(), false));
  const auto& nodal = a.at("sigma_nodal").values;
  const auto& cells = a.at("sigma").values;
  ASSERT_EQ(nodal.size() % 4, 0u);
  ASSERT_FALSE(nodal.empty());
  // σ_yy = −(8/3)·0.01 everywhere (RunControls.RollersGiveTheExactUniaxialSolution).
  for (std::size_t v = 0; v < nodal.size() / 4; ++v) {
    EXPECT_NEAR(nodal[4 * v + 3], cells[3], 1e-6) << v;
    EXPECT_NEAR(nodal[4 * v + 3], -0.08 / 3.0, 1e-6) << v;
    EXPECT_NEAR(nodal[4 * v], 0.0, 1e-6) << v;
  }
  const auto& vm = a.at("von_mises_nodal").values;
  for (std::size_t v = 0; v < vm.size(); ++v) EXPECT_NEAR(vm[v], a.at("von_mises").values[0], 1e-6);
}

}  // namespace
}  // namespace fosls
