import sys
p=sys.argv[1]; red_max=float(sys.argv[2]) if len(sys.argv)>2 else 0.5
R0=5.0; H=7.5  # the default specimen (D0 10, H0 15 mm)
lines=open(p).read().split('\n')
coords={}; blocks=[]; cur=None; mode=None
for l in lines:
    if l.startswith('    2C'): mode='c'; continue
    if l.startswith('  100C'): mode='h'; t=float(l[12:24]); continue
    if l.startswith(' -4  DISP'): mode='d'; cur={}; blocks.append((t,cur)); continue
    if l.startswith(' -3') or l.startswith('    3C'): mode=None; continue
    if l.startswith(' -1') and mode in ('c','d'):
        n=int(l[3:13]); v=[float(l[13+12*i:25+12*i]) for i in range(3)]
        if mode=='c': coords[n]=v
        else: cur[n]=v
lat=sorted([n for n,c in coords.items() if abs(c[0]-R0)<1e-9 and c[1]<=H+1e-9], key=lambda n:-coords[n][1])
for t,d in blocks:
    red=t*red_max; zp=H*(1-red)
    pos=lambda n:(coords[n][0]+d[n][0], coords[n][1]+d[n][1])
    ri=pos(lat[0])[0]; ro=ri; k=0
    for n in lat[1:]:
        r,z=pos(n)
        if zp-z<=1e-4: ro=max(ro,r); k+=1
        else: break
    rmax=max(pos(n)[0] for n in lat)
    print("red %.3f  Ri %.4f Ro %.4f u %.4f nodes %d Rmax %.4f"%(red,ri,ro,ro-ri,k,rmax))
