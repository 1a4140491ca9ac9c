"""An MCAP file as the reference Python reader (mcap, from PyPI) reads it.

Prints JSON: the header's library, and per channel (by topic) its message
encoding, schema encoding, message count, the first message decoded and
whether log times never go back.
"""
import json
import sys

from mcap.reader import make_reader

with open(sys.argv[1], "rb") as f:
    reader = make_reader(f)
    header = reader.get_header()
    channels = {}
    for schema, channel, message in reader.iter_messages():
        c = channels.setdefault(
            channel.topic,
            {
                "messageEncoding": channel.message_encoding,
                "schemaEncoding": schema.encoding,
                "schemaName": schema.name,
                "count": 0,
                "first": json.loads(message.data),
                "firstLogTime": message.log_time,
                "ordered": True,
                "last": 0,
            },
        )
        c["count"] += 1
        c["ordered"] = c["ordered"] and message.log_time >= c["last"]
        c["last"] = message.log_time
    summary = reader.get_summary()
    print(
        json.dumps(
            {
                "library": header.library,
                "channels": channels,
                "statistics": summary.statistics.message_count if summary and summary.statistics else None,
            }
        )
    )
