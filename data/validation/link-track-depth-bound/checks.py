import numpy as np
def seg_hits_poly(p,q,P):
    a=P; b=np.roll(P,-1,axis=0)
    def orient(u,v,w): return (v[...,0]-u[...,0])*(w[...,1]-u[...,1])-(v[...,1]-u[...,1])*(w[...,0]-u[...,0])
    o1=orient(p,q,a); o2=orient(p,q,b); o3=orient(a,b,p[None,:]); o4=orient(a,b,q[None,:])
    return bool(np.any((o1*o2<0)&(o3*o4<0)))
def inside(P,pt):
    x,y=pt; a=P; b=np.roll(P,-1,axis=0)
    m=((a[:,1]>y)!=(b[:,1]>y))
    xi=a[m,0]+(y-a[m,1])*(b[m,0]-a[m,0])/(b[m,1]-a[m,1])
    return int(np.sum(xi>x))%2==1
def dist_pt_poly(P,pt):
    a=P; b=np.roll(P,-1,axis=0); ab=b-a; t=np.clip(((pt-a)*ab).sum(1)/np.maximum((ab*ab).sum(1),1e-30),0,1)
    return np.min(np.linalg.norm(a+ab*t[:,None]-pt,axis=1))

def depth_below(polygons, samples=4001):
    """A function p -> how far p lies below the lowest contour of `polygons` (the stowed
    wing and flap sections) at p's x, the contour tabulated at `samples` x's and taken at
    its nearer end beyond them (as the crate's fairing stage measures depth)."""
    def lowest(x):
        ys = []
        for P in polygons:
            a = P; b = np.roll(P, -1, axis=0)
            m = ((a[:, 0] - x) * (b[:, 0] - x) <= 0) & (a[:, 0] != b[:, 0])
            ys += list(a[m, 1] + (b[m, 1] - a[m, 1]) * (x - a[m, 0]) / (b[m, 0] - a[m, 0]))
        return min(ys) if ys else np.nan
    xs = np.concatenate([P[:, 0] for P in polygons])
    gx = np.linspace(xs.min() + 1e-9, xs.max() - 1e-9, samples)
    gy = np.array([lowest(x) for x in gx])
    return lambda p: np.interp(p[0], gx, gy) - p[1]
