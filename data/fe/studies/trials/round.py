import sys, os, math
p=sys.argv[1]; s=open(p).read()
rc=float(os.environ.get("RC","0.1")); R0=5.0; H=7.5
head, rest = s.split("*NODE,NSET=NALL\n",1)
nodes, tail = rest.split("*ELEMENT",1)
out=[]
for l in nodes.strip().split("\n"):
    a=l.split(","); n=int(a[0]); r=float(a[1]); z=float(a[2])
    if z <= H+1e-9:  # specimen (platen nodes are at z >= H; the z==H row is specimen top... platen starts at z0 too)
        pass
    out.append([n,r,z])
# platen nodes: ids after the specimen; find by NSET PLATENN generate first id
pf=int(s.split("*NSET,NSET=PLATENN,GENERATE\n")[1].split(",")[0])
res=[]
for n,r,z in out:
    if n < pf:
        x = r-(R0-rc); y = z-(H-rc)
        if x>0 and y>0:
            L=math.hypot(x,y); sc=max(x,y)/L
            r=(R0-rc)+x*sc; z=(H-rc)+y*sc
    res.append("%d, %.10g, %.10g"%(n,r,z))
s=head+"*NODE,NSET=NALL\n"+"\n".join(res)+"\n*ELEMENT"+tail
if os.environ.get("S2S"): s = s.replace("TYPE=NODE TO SURFACE", "TYPE=SURFACE TO SURFACE")
open(p,'w').write(s)
