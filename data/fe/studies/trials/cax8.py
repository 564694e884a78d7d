import sys, os, re
p=sys.argv[1]; s=open(p).read()
head, rest = s.split("*NODE,NSET=NALL\n",1)
nodesec, rest2 = rest.split("*ELEMENT,TYPE=CAX4R,ELSET=SPEC\n",1)
spec, rest3 = rest2.split("*ELEMENT,TYPE=CAX4R,ELSET=PLATEN\n",1)
nodes={}
for l in nodesec.strip().split("\n"):
    a=l.split(","); nodes[int(a[0])]=(float(a[1]),float(a[2]))
nid=max(nodes)+1; mid={}
def m(a,b):
    global nid
    k=(min(a,b),max(a,b))
    if k not in mid:
        mid[k]=nid; nodes[nid]=((nodes[a][0]+nodes[b][0])/2,(nodes[a][1]+nodes[b][1])/2); nid+=1
    return mid[k]
els=[]
for l in spec.strip().split("\n"):
    a=[int(x) for x in l.split(",")]
    e,n1,n2,n3,n4=a
    els.append("%d, %d, %d, %d, %d, %d, %d, %d, %d"%(e,n1,n2,n3,n4,m(n1,n2),m(n2,n3),m(n3,n4),m(n4,n1)))
newnodes="\n".join("%d, %.10g, %.10g"%(k,v[0],v[1]) for k,v in sorted(nodes.items()))
axis=[k for k,v in mid.items()]
ax=[v for k,v in mid.items() if nodes[v][0]==0.0]
md=[v for k,v in mid.items() if nodes[v][1]==0.0]
s=head+"*NODE,NSET=NALL\n"+newnodes+"\n*ELEMENT,TYPE=CAX8R,ELSET=SPEC\n"+"\n".join(els)+"\n*ELEMENT,TYPE=CAX4R,ELSET=PLATEN\n"+rest3
def ns(name, ids):
    return "*NSET,NSET=%s\n"%name + "\n".join(", ".join(str(i) for i in ids[j:j+8]) for j in range(0,len(ids),8)) + "\n"
s=s.replace("*NSET,NSET=PLATENN", ns("AXIS",ax)+ns("MID",md)+"*NSET,NSET=PLATENN",1)
if os.environ.get("S2S"): s = s.replace("TYPE=NODE TO SURFACE", "TYPE=SURFACE TO SURFACE")
open(p,'w').write(s)
