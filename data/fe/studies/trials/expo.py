import sys, os
p=sys.argv[1]; s=open(p).read()
c0=os.environ.get("C0","0.01"); p0=os.environ.get("P0","50")
s=s.replace("*SURFACE BEHAVIOR,PRESSURE-OVERCLOSURE=LINEAR\n100000, 0.1\n","*SURFACE BEHAVIOR,PRESSURE-OVERCLOSURE=EXPONENTIAL\n%s, %s\n"%(c0,p0))
if os.environ.get("S2S"): s = s.replace("TYPE=NODE TO SURFACE", "TYPE=SURFACE TO SURFACE")
open(p,'w').write(s)
