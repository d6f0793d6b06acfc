#!/usr/bin/env python3
"""Checks that docs/protocol.md documents proto/impulse.proto exactly.

Every message of the schema must have a `### `Name`` section in the page
with a table of its fields (`| number | `name` | `type` | meaning |`), and
every enum a `### enum `Name`` section with its values; the page may not
describe a message, field or value the schema lacks. Types are written as in
the schema: `double`, `Vec2`, `repeated Vec2`, `optional double`, and
`oneof kind: Circle` for a member of a oneof.

The schema is read through protoc (a descriptor set), so comments and layout
of the .proto cannot fool the check.

usage: protocol_doc_test.py [--self-test] PROTOC PROTO_FILE DOC_FILE
(--self-test: checks that a page with a field missing, a number changed and
a message the schema lacks is refused, each for its reason.)
"""
import re
import subprocess
import sys
import tempfile
from pathlib import Path

from google.protobuf import descriptor_pb2

SCALARS = {
    descriptor_pb2.FieldDescriptorProto.TYPE_DOUBLE: "double",
    descriptor_pb2.FieldDescriptorProto.TYPE_FLOAT: "float",
    descriptor_pb2.FieldDescriptorProto.TYPE_INT64: "int64",
    descriptor_pb2.FieldDescriptorProto.TYPE_UINT64: "uint64",
    descriptor_pb2.FieldDescriptorProto.TYPE_INT32: "int32",
    descriptor_pb2.FieldDescriptorProto.TYPE_FIXED64: "fixed64",
    descriptor_pb2.FieldDescriptorProto.TYPE_FIXED32: "fixed32",
    descriptor_pb2.FieldDescriptorProto.TYPE_BOOL: "bool",
    descriptor_pb2.FieldDescriptorProto.TYPE_STRING: "string",
    descriptor_pb2.FieldDescriptorProto.TYPE_BYTES: "bytes",
    descriptor_pb2.FieldDescriptorProto.TYPE_UINT32: "uint32",
    descriptor_pb2.FieldDescriptorProto.TYPE_SFIXED32: "sfixed32",
    descriptor_pb2.FieldDescriptorProto.TYPE_SFIXED64: "sfixed64",
    descriptor_pb2.FieldDescriptorProto.TYPE_SINT32: "sint32",
    descriptor_pb2.FieldDescriptorProto.TYPE_SINT64: "sint64",
}


def schema_of(protoc, proto_file):
    """{("message"|"enum", name): {(number, name, type)}} from the .proto."""
    proto_file = Path(proto_file).resolve()
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "schema.pb"
        subprocess.run([protoc, f"-I{proto_file.parent}", f"--descriptor_set_out={out}",
                        str(proto_file)], check=True)
        files = descriptor_pb2.FileDescriptorSet.FromString(out.read_bytes())
    schema = {}
    for file in files.file:
        for message in file.message_type:
            if message.nested_type or message.enum_type:
                sys.exit(f"{message.name}: nested types are not supported by this check")
            rows = set()
            for field in message.field:
                kind = SCALARS.get(field.type) or field.type_name.rsplit(".", 1)[-1]
                if field.proto3_optional:
                    kind = "optional " + kind
                elif field.label == descriptor_pb2.FieldDescriptorProto.LABEL_REPEATED:
                    kind = "repeated " + kind
                elif field.HasField("oneof_index"):
                    kind = f"oneof {message.oneof_decl[field.oneof_index].name}: {kind}"
                rows.add((field.number, field.name, kind))
            schema[("message", message.name)] = rows
        for enum in file.enum_type:
            schema[("enum", enum.name)] = {(value.number, value.name, "") for value in enum.value}
    return schema


HEADING = re.compile(r"^###\s+(enum\s+)?`([A-Za-z0-9_]+)`\s*$")
CELL = re.compile(r"^`([^`]*)`$")


def doc_of(doc_file):
    """The same shape as schema_of, read from the page's sections and tables."""
    doc = {}
    errors = []
    current = None
    for number, line in enumerate(Path(doc_file).read_text().splitlines(), 1):
        heading = HEADING.match(line)
        if heading:
            current = ("enum" if heading.group(1) else "message", heading.group(2))
            if current in doc:
                errors.append(f"{doc_file}:{number}: {current[0]} {current[1]} described twice")
            doc[current] = set()
            continue
        if line.startswith("#"):
            current = None
            continue
        if current is None or not line.startswith("|"):
            continue
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if not cells[0].isdigit():
            continue  # the header and its rule
        name = CELL.match(cells[1]) if len(cells) > 1 else None
        if current[0] == "message":
            kind = CELL.match(cells[2]) if len(cells) > 2 else None
            if not (name and kind) or len(cells) != 4:
                errors.append(f"{doc_file}:{number}: expected | N | `name` | `type` | meaning |")
                continue
            doc[current].add((int(cells[0]), name.group(1), kind.group(1)))
        else:
            if not name or len(cells) != 3:
                errors.append(f"{doc_file}:{number}: expected | N | `VALUE` | meaning |")
                continue
            doc[current].add((int(cells[0]), name.group(1), ""))
    return doc, errors


def compare(schema, doc):
    errors = []
    for key in sorted(schema.keys() - doc.keys()):
        errors.append(f"{key[0]} {key[1]} is in the schema but not in the page")
    for key in sorted(doc.keys() - schema.keys()):
        errors.append(f"{key[0]} {key[1]} is in the page but not in the schema")
    for key in sorted(schema.keys() & doc.keys()):
        for row in sorted(schema[key] - doc[key]):
            errors.append(f"{key[0]} {key[1]}: the schema has {row[0]} {row[1]} {row[2]}".rstrip()
                          + ", the page does not")
        for row in sorted(doc[key] - schema[key]):
            errors.append(f"{key[0]} {key[1]}: the page has {row[0]} {row[1]} {row[2]}".rstrip()
                          + ", the schema does not")
    return errors


def self_test(schema, doc):
    """Spoils a copy of the page three ways; each must be reported."""
    spoiled = {key: set(rows) for key, rows in doc.items()}
    welcome = spoiled[("message", "Welcome")]
    dropped = max(welcome)
    welcome.discard(dropped)
    hello = spoiled[("message", "Hello")]
    renumbered = min(hello)
    hello.discard(renumbered)
    hello.add((renumbered[0] + 1000,) + renumbered[1:])
    spoiled[("message", "NoSuchMessage")] = set()
    errors = compare(schema, spoiled)
    expected = [f"message Welcome: the schema has {dropped[0]} {dropped[1]}",
                f"message Hello: the page has {renumbered[0] + 1000} {renumbered[1]}",
                "message NoSuchMessage is in the page but not in the schema"]
    missed = [e for e in expected if not any(error.startswith(e) for error in errors)]
    for miss in missed:
        print(f"self-test: not reported: {miss}")
    print(f"self-test: {len(errors)} disagreements reported for 3 spoilt entries")
    return 1 if missed or len(errors) != 4 else 0


def main():
    args = sys.argv[1:]
    testing = args[:1] == ["--self-test"]
    if testing:
        args = args[1:]
    if len(args) != 3:
        sys.exit(__doc__)
    protoc, proto_file, doc_file = args
    schema = schema_of(protoc, proto_file)
    doc, errors = doc_of(doc_file)
    if testing:
        return self_test(schema, doc)
    errors += compare(schema, doc)
    for error in errors:
        print(error)
    fields = sum(len(rows) for rows in schema.values())
    if errors:
        print(f"FAILED: {len(errors)} disagreements between {proto_file} and {doc_file}")
        return 1
    print(f"ok: {len(schema)} messages and enums, {fields} fields and values documented")
    return 0


if __name__ == "__main__":
    sys.exit(main())
