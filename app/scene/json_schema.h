#pragma once
// Field tables (app/scene/field_table.h) as a JSON Schema, draft 2020-12: the root table's fields
// inline, every table it reaches under $defs, each object closed (additionalProperties: false, as
// the loaders refuse unknown keys), each field's `expected` words as its description. Editors
// (VS Code's "$schema" or json.schemas setting, JetBrains, any validator) check and complete
// input files with it; `tumble schema scene|suite` prints it.
#include "app/scene/field_table.h"

#include <nlohmann/json.hpp>

#include <string>

namespace tumble::app {

nlohmann::ordered_json json_schema(const Table& root, const std::string& id,
                                   const std::string& title);

} // namespace tumble::app
