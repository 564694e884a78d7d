import sys, os, re
p=sys.argv[1]; s=open(p).read()
head, rest = s.split("*ELEMENT,TYPE=CAX4R,ELSET=SPEC\n",1)
spec, rest2 = rest.split("*ELEMENT,TYPE=CAX4R,ELSET=PLATEN\n",1)
lines=spec.strip().split("\n")
# slave surface lines tell the corner element: the last S3 line and the last S2 line share it
surf=s.split("*SURFACE,NAME=SLAVE\n")[1].split("*SURFACE,NAME=MASTER")[0].strip().split("\n")
s3=[int(l.split(",")[0]) for l in surf if "S3" in l]; s2=[int(l.split(",")[0]) for l in surf if "S2" in l]
E=max(s3); assert E==max(s2)
keep=[]; tri=None
for l in lines:
    a=[int(x) for x in l.split(",")]
    if a[0]==E: tri=a
    else: keep.append(l)
e,n1,n2,n3,n4=tri
s=head+"*ELEMENT,TYPE=CAX4R,ELSET=SPEC\n"+"\n".join(keep)+"\n*ELEMENT,TYPE=CAX3,ELSET=SPEC\n%d, %d, %d, %d\n%d, %d, %d, %d\n"%(E,n1,n2,n3,900000,n1,n3,n4)+"*ELEMENT,TYPE=CAX4R,ELSET=PLATEN\n"+rest2
s=s.replace("%d, S3\n%d, S2"%(E,1+0),"X")  # no-op guard
surf_new=[]
for l in surf:
    e_,f=l.split(","); e_=int(e_); f=f.strip()
    if e_==E and f=="S3": surf_new.append("900000, S2")
    elif e_==E and f=="S2": surf_new.append("%d, S2"%E)
    else: surf_new.append(l)
s=s.replace("*SURFACE,NAME=SLAVE\n"+"\n".join(surf)+"\n","*SURFACE,NAME=SLAVE\n"+"\n".join(surf_new)+"\n")
if os.environ.get("S2S"): s = s.replace("TYPE=NODE TO SURFACE", "TYPE=SURFACE TO SURFACE")
open(p,'w').write(s)
