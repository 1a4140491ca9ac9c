"""An ELAN document as pympi, the reference Python library for ELAN, reads it.

Prints JSON: every tier's annotations as [start_ms, end_ms, value], in time
order, and the linked media descriptors.
"""
import json
import sys

import pympi

eaf = pympi.Elan.Eaf(sys.argv[1])
print(
    json.dumps(
        {
            "tiers": {t: sorted(eaf.get_annotation_data_for_tier(t)) for t in eaf.get_tier_names()},
            "media": eaf.media_descriptors,
        }
    )
)
