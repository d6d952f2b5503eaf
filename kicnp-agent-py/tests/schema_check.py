"""A JSON Schema checker for the keywords docs/protocol/schemas uses (type, const, enum, properties, required,
additionalProperties, items, $ref to $defs, oneOf, minimum, maximum, maxLength): the standard library has none, and
the SDK's tests must not need a package."""

_TYPES = {"object": dict, "array": list, "string": str, "boolean": bool}


def problems(value, schema, root=None, where="$"):
    """Every way ``value`` breaks ``schema``, each naming its place; empty when it conforms."""
    root = root or schema
    if "$ref" in schema:
        return problems(value, root["$defs"][schema["$ref"].split("/")[-1]], root, where)
    found = []
    kind = schema.get("type")
    if kind is not None and not _is(value, kind):
        return ["%s is %r, not of type %s" % (where, value, kind)]
    if "const" in schema and value != schema["const"]:
        found.append("%s is %r, not %r" % (where, value, schema["const"]))
    if "enum" in schema and value not in schema["enum"]:
        found.append("%s is %r, not one of %s" % (where, value, schema["enum"]))
    if "minimum" in schema and value < schema["minimum"] or "maximum" in schema and value > schema["maximum"]:
        found.append("%s is %r, out of range" % (where, value))
    if "maxLength" in schema and len(value) > schema["maxLength"]:
        found.append("%s is %d characters long, more than %d" % (where, len(value), schema["maxLength"]))
    if isinstance(value, dict):
        found += ["%s lacks '%s'" % (where, name) for name in schema.get("required", ()) if name not in value]
        properties = schema.get("properties", {})
        for name, member in value.items():
            if name in properties:
                found += problems(member, properties[name], root, "%s.%s" % (where, name))
            elif schema.get("additionalProperties") is False:
                found.append("%s has the member '%s', which is not allowed" % (where, name))
            elif isinstance(schema.get("additionalProperties"), dict):
                found += problems(member, schema["additionalProperties"], root, "%s.%s" % (where, name))
    if isinstance(value, list) and "items" in schema:
        for i, item in enumerate(value):
            found += problems(item, schema["items"], root, "%s[%d]" % (where, i))
    if "oneOf" in schema:
        matching = sum(1 for option in schema["oneOf"] if not problems(value, option, root, where))
        if matching != 1:
            found.append("%s matches %d of the oneOf schemas, not exactly 1" % (where, matching))
    return found


def _is(value, kind):
    if kind == "integer":
        return isinstance(value, int) and not isinstance(value, bool)
    if kind == "number":
        return isinstance(value, (int, float)) and not isinstance(value, bool)
    return isinstance(value, _TYPES[kind])
