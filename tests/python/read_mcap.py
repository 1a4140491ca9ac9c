"""An MCAP file as the reference Python reader (mcap, from PyPI) reads it,
checked as Foxglove's `mcap doctor` would where Python can: every record's
CRC, the summary's counts against the messages, each JSON Schema valid, and
each message valid against its channel's schema (jsonschema, from PyPI).

Prints JSON: the header's library, the schemas (id, name, encoding, the
schema), and per channel (by topic) its encodings, schema id and name,
message count, every message decoded with its log time (nanoseconds, as
text: they pass what a float holds), whether log times never go back and
publish times equal log times; then every problem found.
"""
import json
import sys

from jsonschema import Draft202012Validator
from mcap.reader import make_reader
from mcap.records import Channel, Message, Schema
from mcap.stream_reader import StreamReader

problems = []
path = sys.argv[1]

# The whole file record by record, its CRCs checked.
schemas, channels, counts = {}, {}, {}
with open(path, "rb") as f:
    for record in StreamReader(f, validate_crcs=True).records:
        if isinstance(record, Schema):
            schemas[record.id] = record
        elif isinstance(record, Channel):
            channels[record.id] = record
        elif isinstance(record, Message):
            counts[record.channel_id] = counts.get(record.channel_id, 0) + 1

validators = {}
for schema in schemas.values():
    if schema.encoding != "jsonschema":
        problems.append(f"schema {schema.name}: encoding {schema.encoding}, not jsonschema")
        continue
    document = json.loads(schema.data)
    try:
        Draft202012Validator.check_schema(document)
    except Exception as error:  # noqa: BLE001 - the problem is reported, not raised
        problems.append(f"schema {schema.name}: not a valid JSON Schema: {error}")
    validators[schema.id] = Draft202012Validator(document)

with open(path, "rb") as f:
    reader = make_reader(f)
    header = reader.get_header()
    summary = reader.get_summary()
    topics = {}
    for schema, channel, message in reader.iter_messages():
        decoded = json.loads(message.data)
        c = topics.setdefault(
            channel.topic,
            {
                "messageEncoding": channel.message_encoding,
                "schemaEncoding": schema.encoding,
                "schemaId": schema.id,
                "schemaName": schema.name,
                "count": 0,
                "messages": [],
                "logTimes": [],
                "ordered": True,
                "publishedWhenLogged": True,
            },
        )
        c["count"] += 1
        c["messages"].append(decoded)
        c["ordered"] = c["ordered"] and (not c["logTimes"] or message.log_time >= int(c["logTimes"][-1]))
        c["logTimes"].append(str(message.log_time))
        c["publishedWhenLogged"] = c["publishedWhenLogged"] and message.publish_time == message.log_time
        for error in validators[schema.id].iter_errors(decoded) if schema.id in validators else []:
            problems.append(f"{channel.topic} message {message.sequence}: {error.message}")

stats = summary.statistics if summary else None
if stats is None:
    problems.append("no statistics in the summary")
else:
    if stats.message_count != sum(counts.values()):
        problems.append(f"statistics count {stats.message_count} messages, the file holds {sum(counts.values())}")
    if stats.channel_message_counts != counts:
        problems.append(f"statistics count {stats.channel_message_counts} by channel, the file holds {counts}")
for channel in channels.values():
    if channel.schema_id not in schemas:
        problems.append(f"channel {channel.topic}: schema {channel.schema_id} is not in the file")

print(
    json.dumps(
        {
            "library": header.library,
            "schemas": [
                {"id": s.id, "name": s.name, "encoding": s.encoding, "schema": json.loads(s.data)}
                for s in schemas.values()
            ],
            "channels": topics,
            "statistics": stats.message_count if stats else None,
            "problems": problems,
        }
    )
)
