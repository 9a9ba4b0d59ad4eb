"""Every link-track on a grid of fixed pivots O (0.1 m over x -1..2.5 m, y -0.8..1.0 m,
station frame) and track directions (every 1 deg), with relaxed region rules: O in the wing
or below the sections' lower contour (not in the flap), the link point A and the carriage C
below that contour or inside the flap; the settings reached in order on one branch; records
each loop's depth (A, C and O below the contour over 49 samples, no radii) and its smallest
transmission angle. Usage: explore_lt.py REPORT.json OUT.pkl (a link-track report of
`flapwright study`); filter_lt.py then applies the checks over the deployment."""
import numpy as np, sys
from poses import load
from checks import depth_below

class Path:
    def __init__(self,P): self.P=np.asarray(P)
    def contains_point(self,p):
        x,y=p; P=self.P; a=P; b=np.roll(P,-1,axis=0)
        m=((a[:,1]>y)!=(b[:,1]>y))
        xi=a[m,0]+(y-a[m,1])*(b[m,0]-a[m,0])/(b[m,1]-a[m,1])
        return int(np.sum(xi>x))%2==1
poses,polys,s=load(sys.argv[1])
cf=None
wing=polys['wing'][0]; flap=polys['outboard'][0]
allp=[wing,flap]
depth=depth_below(allp)
fl_x=flap[:,0]; cf=fl_x.max()-fl_x.min(); print('flap chord',cf, 'nose', fl_x.max())
wpath=Path(wing); fpath=Path(flap)
def rot(t): return np.array([[np.cos(t),-np.sin(t)],[np.sin(t),np.cos(t)]])
def carriage_point(d):
    m=np.array([d[1],-d[0]]); M=[];rhs=[]
    for R,t,_ in poses:
        M.append((R-np.eye(2)).T@m); rhs.append(-m@t)
    M=np.array(M)
    if abs(np.linalg.det(M))<1e-12: return None
    return np.linalg.solve(M,np.array(rhs))
def link_point(o):
    M=[];rhs=[]
    for R,t,_ in poses:
        M.append(2*(R.T@(t-o)+o)); rhs.append(o@o-(t-o)@(t-o))
    M=np.array(M)
    if abs(np.linalg.det(M))<1e-12: return None
    return np.linalg.solve(M,np.array(rhs))
def turn(o,a,b):
    u=a-o;v=b-o; return np.arctan2(u[0]*v[1]-u[1]*v[0],u@v)
def loop(o,a,c,d,N=48):
    span=np.linalg.norm(c-a); b0=d@(c-a); br=np.sign(b0)
    turns=[turn(o,a,R@a+t) for R,t,_ in poses]
    if not(turns[0]*turns[1]>0 and abs(turns[0])<abs(turns[1]) and abs(turns[1])<np.radians(150)): return None
    dep=0; mu=9; cs=[]
    for k in range(N+1):
        ph=turns[1]*k/N
        A=o+rot(ph)@(a-o); to_c=c-A; b=d@to_c; disc=b*b-(to_c@to_c-span**2)
        if disc<0: return None
        root=np.sqrt(disc); lam=-b+br*root; C=c+d*lam
        mu=min(mu,np.arcsin(min(1,root/span)))
        dep=max(dep,depth(A),depth(C)); cs.append(C)
    # settings on branch
    for (R,t,_),tu in zip(poses,turns):
        A=o+rot(tu)@(a-o); to_c=c-A; b=d@to_c; disc=b*b-(to_c@to_c-span**2)
        if disc<0: return None
        C=c+d*(-b+br*np.sqrt(disc))
        if np.linalg.norm(C-(R@c+t))>1e-6: return None
    return dep,mu,turns
# candidates
Cs=[]
for k in range(360):
    d=np.array([np.cos(np.radians(k)),np.sin(np.radians(k))])
    c=carriage_point(d)
    if c is None: continue
    tr=[d@(R@c+t-c) for R,t,_ in poses]
    if not(tr[0]>0 and tr[1]>tr[0]): continue
    if wpath.contains_point(c): continue
    if not (depth(c)>=0 or fpath.contains_point(c)): continue
    Cs.append((k,c,d))
print(len(Cs),'carriages')
Os=[]
for x in np.linspace(-1.0,2.5,36):
    for y in np.linspace(-0.8,1.0,37):
        Os.append(np.array([x,y]))
res=[]
for o in Os:
    oin=wpath.contains_point(o)
    if not (oin or (depth(o)>0 and not fpath.contains_point(o))): continue
    a=link_point(o)
    if a is None: continue
    if wpath.contains_point(a): continue
    if not (depth(a)>=0 or fpath.contains_point(a)): continue
    for k,c,d in Cs:
        r=loop(o,a,c,d)
        if r is None: continue
        dep,mu,tu=r
        dep=max(dep,depth(o)); res.append((dep/cf*100,np.degrees(mu),k,o,a,c,wpath.contains_point(o)))
res.sort(key=lambda r:r[0])
import pickle; pickle.dump([(r[0],r[1],r[2],r[3],r[4],r[5],r[6]) for r in res],open(sys.argv[2],'wb'))
