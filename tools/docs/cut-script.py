#!/usr/bin/env python3
"""Cuts a billiards-input-script/1 at one moment, so that a window shot
(tools/docs/window-shot.sh) keeps it: the game idles HOLD seconds there and closes on it.

    python3 tools/docs/cut-script.py IN.json KEY N HOLD OUT.json          after the wait that follows the N-th press of KEY
    python3 tools/docs/cut-script.py IN.json KEY N HOLD OUT.json before   just before the N-th press of KEY
"""
import json
import sys

source, key, n, hold, out = sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
before = len(sys.argv) > 6 and sys.argv[6] == "before"
script = json.load(open(source))
events, presses = [], 0
for e in script["events"]:
    if e.get("key_down") == key:
        presses += 1
        if before and presses == n:
            break
    events.append(e)
    if not before and presses == n and "wait" in e:
        break
else:
    sys.exit(f"cut-script.py: {source} has no {'press' if before else 'wait after press'} {n} of {key}")
script["events"] = events
script["duration"] = events[-1]["t"] + hold
json.dump(script, open(out, "w"), indent=1)
