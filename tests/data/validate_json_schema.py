#!/usr/bin/python3
# Validates JSON files against a JSON Schema (draft 2020-12) with Debian's python3-jsonschema, for
# tests/app/scene/schema_test.cpp: `validate_json_schema.py SCHEMA FILE...` checks the schema itself,
# then prints one line per file, "valid FILE" or "invalid FILE: <path>: <message>", and exits 0
# (2 when the schema is not a valid draft 2020-12 schema).
import json
import sys

import jsonschema

schema = json.load(open(sys.argv[1]))
try:
    jsonschema.Draft202012Validator.check_schema(schema)
except jsonschema.SchemaError as e:
    print("bad schema:", e.message)
    sys.exit(2)
validator = jsonschema.Draft202012Validator(schema)
for name in sys.argv[2:]:
    errors = list(validator.iter_errors(json.load(open(name))))
    if not errors:
        print("valid", name)
        continue
    first = min(errors, key=lambda e: len(e.path))
    print("invalid %s: /%s: %s" % (name, "/".join(map(str, first.path)), first.message[:160]))
