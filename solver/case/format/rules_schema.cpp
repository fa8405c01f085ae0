#include "case/format/rules_schema.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace fosls {

namespace {

using nlohmann::json;

/// Integral values as JSON integers (200, not 200.0).
json number(double v) {
  if (v == static_cast<double>(static_cast<long long>(v))) return static_cast<long long>(v);
  return v;
}

class SchemaWriter {
 public:
  json value(const ValueRule& rule) {
    json s = kind(rule);
    if (!rule.notes.empty()) s["$comment"] = rule.notes;
    return s;
  }

  json object(const ObjectRule& rule) {
    json s = {{"type", "object"}, {"title", rule.title}};
    if (!rule.notes.empty()) s["$comment"] = rule.notes;
    json alternatives = json::array();
    for (const auto& e : rule.exclusive) alternatives.push_back(exclusive(e));
    if (rule.discriminator.empty()) {
      s["properties"] = properties(rule.fields);
      s["required"] = required(rule.fields);
      s["additionalProperties"] = false;
    } else {
      json values = json::array();
      json variants = json::array();
      for (const auto& v : rule.variants) {
        if (!v.refused.empty()) continue;
        values.push_back(v.value);
        json fields = properties(rule.fields);
        fields.update(properties(v.fields));
        fields[rule.discriminator] = {{"const", v.value}};
        json req = required(rule.fields);
        for (const auto& f : v.fields)
          if (f.required) req.push_back(f.key);
        req.push_back(rule.discriminator);
        json variant = {{"title", v.title},
                        {"description", v.meaning},
                        {"properties", fields},
                        {"required", req},
                        {"additionalProperties", false}};
        if (!v.notes.empty()) variant["$comment"] = v.notes;
        if (v.exclusive.size() == 1) variant.update(exclusive(v.exclusive[0]));
        variants.push_back(variant);
      }
      s["required"] = {rule.discriminator};
      s["properties"] = {
          {rule.discriminator, {{"enum", values}, {"description", rule.discriminator_meaning}}}};
      alternatives.push_back({{"oneOf", variants}});
    }
    if (alternatives.size() == 1)
      s.update(alternatives[0]);
    else if (!alternatives.empty())
      s["allOf"] = alternatives;
    return s;
  }

  json defs() const { return defs_; }

 private:
  json kind(const ValueRule& rule) {
    json s;
    switch (rule.kind) {
      case ValueKind::kNumber:
        s = {{"type", "number"}};
        bounds(rule.range, s);
        break;
      case ValueKind::kInteger:
        s = {{"type", "integer"}};
        bounds(rule.range, s);
        break;
      case ValueKind::kString:
        s = {{"type", "string"}};
        if (rule.range.has_hi()) s["maxLength"] = number(rule.range.hi);
        break;
      case ValueKind::kName:
        s = {{"type", "string"},
             {"minLength", 1},
             {"maxLength", number(rule.range.hi)},
             {"pattern", "^[^\\u0000-\\u001f\\u007f]*$"}};
        break;
      case ValueKind::kChoice:
        if (rule.choices.size() == 1)
          s = {{"const", rule.choices[0]}};
        else
          s = {{"type", "string"}, {"enum", rule.choices}};
        break;
      case ValueKind::kScalar:
        s = {{"type", json::array({"number", "string"})},
             {"maxLength", number(rule.range.hi)},
             {"description", rule.variables == 3
                                 ? "a number, or an expression of x, y and z (muParser syntax)"
                                 : "a number, or an expression of x and y (muParser syntax)"}};
        break;
      case ValueKind::kNull:
        s = {{"type", "null"}};
        break;
      case ValueKind::kBoolean:
        s = {{"type", "boolean"}};
        break;
      case ValueKind::kArray:
        s = {{"type", "array"}, {"items", value(*rule.element)}};
        if (rule.range.lo > 0) s["minItems"] = number(rule.range.lo);
        if (rule.range.has_hi()) s["maxItems"] = number(rule.range.hi);
        break;
      case ValueKind::kMap: {
        json names = value(*rule.key);
        names.erase("type");
        s = {{"type", "object"},
             {"propertyNames", names},
             {"additionalProperties", value(*rule.element)},
             {"minProperties", number(rule.range.lo)},
             {"maxProperties", number(rule.range.hi)}};
        break;
      }
      case ValueKind::kObject: {
        const std::string& anchor = rule.object->anchor;
        if (!defs_.contains(anchor)) {
          defs_[anchor] = json::object();  // a placeholder against recursion
          defs_[anchor] = object(*rule.object);
        }
        s = {{"$ref", "#/$defs/" + anchor}};
        break;
      }
      case ValueKind::kOneOf: {
        json alternatives = json::array();
        for (const auto& a : rule.alternatives) alternatives.push_back(value(a));
        s = {{"oneOf", alternatives}};
        break;
      }
    }
    return s;
  }

  static void bounds(const Range& r, json& s) {
    if (r.has_lo()) s[r.lo_open ? "exclusiveMinimum" : "minimum"] = number(r.lo);
    if (r.has_hi()) s[r.hi_open ? "exclusiveMaximum" : "maximum"] = number(r.hi);
  }

  json properties(const std::vector<FieldRule>& fields) {
    json p = json::object();
    for (const auto& f : fields) {
      if (!f.refused.empty()) continue;  // the other dimension's: not allowed here
      json s = value(f.value);
      if (s.contains("$ref")) s = {{"allOf", {s}}};  // keep the description beside the $ref
      s["description"] = f.meaning;
      if (!f.default_value.is_null()) s["default"] = f.default_value;
      p[f.key] = s;
    }
    return p;
  }

  static json required(const std::vector<FieldRule>& fields) {
    json r = json::array();
    for (const auto& f : fields)
      if (f.required && f.refused.empty()) r.push_back(f.key);
    return r;
  }

  /// Exactly one set given: each alternative requires its set and none of the others' fields.
  static json exclusive(const ExclusiveFields& e) {
    json alternatives = json::array();
    for (std::size_t i = 0; i < e.sets.size(); ++i) {
      json others = json::array();
      for (std::size_t k = 0; k < e.sets.size(); ++k)
        if (k != i)
          for (const auto& key : e.sets[k]) others.push_back({{"required", {key}}});
      alternatives.push_back({{"required", e.sets[i]}, {"not", {{"anyOf", others}}}});
    }
    return {{"oneOf", alternatives}};
  }

  json defs_ = json::object();
};

}  // namespace

namespace {

/// Replaces every "$ref": "#/$defs/<old>" of `s` by the name `renamed` gives it.
void rename_refs(json& s, const std::map<std::string, std::string>& renamed) {
  if (s.is_object()) {
    for (auto& [key, value] : s.items()) {
      if (key == "$ref" && value.is_string()) {
        const std::string target = value.get<std::string>().substr(std::string("#/$defs/").size());
        if (auto it = renamed.find(target); it != renamed.end()) value = "#/$defs/" + it->second;
      } else {
        rename_refs(value, renamed);
      }
    }
  } else if (s.is_array()) {
    for (auto& value : s) rename_refs(value, renamed);
  }
}

/// Whether `s` refers to any of `names` in $defs.
bool refers_to(const json& s, const std::set<std::string>& names) {
  if (s.is_object()) {
    for (const auto& [key, value] : s.items())
      if (key == "$ref" && value.is_string()
              ? names.count(value.get<std::string>().substr(std::string("#/$defs/").size())) > 0
              : refers_to(value, names))
        return true;
  } else if (s.is_array()) {
    for (const auto& value : s)
      if (refers_to(value, names)) return true;
  }
  return false;
}

}  // namespace

json rules_json_schema_by_dimension(const ObjectRule& root2, const ObjectRule& root3,
                                    const std::string& id, const std::string& description) {
  SchemaWriter w2, w3;
  const json s2 = w2.object(root2), s3 = w3.object(root3);
  json defs2 = w2.defs(), defs3 = w3.defs();
  defs2[root2.anchor] = s2;
  defs3[root3.anchor] = s3;
  // A definition differs by dimension when its text does, or when it refers to one that does
  // (its 2D and 3D copies then point at different objects).
  std::set<std::string> differ;
  for (const auto& [name, d] : defs2.items())
    if (!defs3.contains(name) || defs3[name] != d) differ.insert(name);
  for (const auto& [name, d] : defs3.items())
    if (!defs2.contains(name)) differ.insert(name);
  for (bool grew = true; grew;) {
    grew = false;
    for (const auto& [name, d] : defs2.items())
      if (!differ.count(name) && (refers_to(d, differ) || refers_to(defs3[name], differ)))
        grew |= differ.insert(name).second;
  }
  std::map<std::string, std::string> as2, as3;
  for (const auto& name : differ) as2[name] = name + "_2d", as3[name] = name + "_3d";
  json defs = json::object();
  for (auto [defs_d, as] : {std::pair{&defs2, &as2}, std::pair{&defs3, &as3}})
    for (auto& [name, d] : defs_d->items()) {
      rename_refs(d, *as);
      defs[as->count(name) ? as->at(name) : name] = d;
    }
  const std::string root2_name = as2.count(root2.anchor) ? as2[root2.anchor] : root2.anchor;
  const std::string root3_name = as3.count(root3.anchor) ? as3[root3.anchor] : root3.anchor;
  return {{"$schema", "https://json-schema.org/draft/2020-12/schema"},
          {"$id", id},
          {"description", description},
          {"$comment",
           "one schema for both dimensions: a document with \"dimension\": 3 is checked against " +
               root3_name + ", any other against " + root2_name},
          {"if", {{"properties", {{"dimension", {{"const", 3}}}}}, {"required", {"dimension"}}}},
          {"then", {{"$ref", "#/$defs/" + root3_name}}},
          {"else", {{"$ref", "#/$defs/" + root2_name}}},
          {"$defs", defs}};
}

json rules_json_schema(const ObjectRule& root, const std::string& id,
                       const std::string& description) {
  SchemaWriter writer;
  json schema = {{"$schema", "https://json-schema.org/draft/2020-12/schema"},
                 {"$id", id},
                 {"description", description}};
  schema.update(writer.object(root));
  const json defs = writer.defs();
  if (!defs.empty()) schema["$defs"] = defs;
  return schema;
}

}  // namespace fosls
