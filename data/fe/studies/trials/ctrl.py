import sys, os
p = sys.argv[1]; s = open(p).read()
ctl = os.environ.get("CTL", "8,10,9,50,10,4,,20")
field = os.environ.get("FIELD", "")
lines = s.split("\n"); out = []
i = 0
while i < len(lines):
    out.append(lines[i])
    if lines[i].startswith("*STATIC"):
        out.append(lines[i+1]); i += 1
        out.append("*CONTROLS,PARAMETERS=TIME INCREMENTATION"); out.append(ctl)
        if field: out.append("*CONTROLS,PARAMETERS=FIELD"); out.append(field)
    i += 1
s = "\n".join(out)
if os.environ.get("S2S"): s = s.replace("TYPE=NODE TO SURFACE", "TYPE=SURFACE TO SURFACE")
if os.environ.get("INC"): 
    import re
    s = re.sub(r"(\*STATIC\n)([^\n]*)", lambda m: m.group(1) + os.environ["INC"], s)
if os.environ.get("STICK"): s = s.replace("*FRICTION\n", "*FRICTION\n").replace(", 10000\n*CONTACT", ", %s\n*CONTACT" % os.environ["STICK"])
open(p, "w").write(s)
