"""The loops explore_lt.py kept, shallowest first, through checks over the deployment
(49 samples): the smallest transmission angle at least 30 deg; the flap never within 5 cm
of O nor 9 mm of the wing's trailing edge; A and C never inside the wing; the link not
through the wing (O outside it) nor the flap (A outside it); the track beam (stowed to
landing carriage) not through the wing, nor the moving flap (C outside it). Prints the 12
shallowest that pass and the count of each first failure. Usage: filter_lt.py REPORT.json
IN.pkl [ain] (ain: A may sit inside the flap)."""
import numpy as np, sys, pickle
from poses import load
from checks import *
poses,polys,s=load(sys.argv[1]); res=pickle.load(open(sys.argv[2],'rb'))
wing=polys['wing'][0]; flap=polys['outboard'][0]
cf=flap[:,0].max()-flap[:,0].min()
import os
LIPC=float(os.environ.get('LIPC','0.009'))
LIP=np.array(s['flap_position']['trailing_edge_st_m'])
def rot(t): return np.array([[np.cos(t),-np.sin(t)],[np.sin(t),np.cos(t)]])
def turn(o,a,b):
    u=a-o;v=b-o; return np.arctan2(u[0]*v[1]-u[1]*v[0],u@v)
def loop_poses(o,a,c,d,turns,span,br):
    """The link point, the carriage and the flap's section at 49 samples of the link's turn."""
    for kk in range(49):
        ph=turns[1]*kk/48
        A=o+rot(ph)@(a-o); to_c=c-A; b=d@to_c; disc=b*b-(to_c@to_c-span**2)
        C=c+d*(-b+br*np.sqrt(max(disc,0)))
        v0=c-a; v1=C-A; th=np.arctan2(v0[0]*v1[1]-v0[1]*v1[0], v0@v1)
        yield A,C,(rot(th)@(flap-a).T).T+A
allow_a_in_flap = len(sys.argv)>3
shown=0; stats={}
for dep,mu,k,o,a,c,oin in res:
    if mu<30: continue
    d=np.array([np.cos(np.radians(k)),np.sin(np.radians(k))])
    span=np.linalg.norm(c-a); br=np.sign(d@(c-a))
    turns=[turn(o,a,R@a+t) for R,t,_ in poses]
    ok=True; why=''
    ain=inside(flap,a); cin=inside(flap,c)
    if ain and not allow_a_in_flap: ok=False; why='A in flap'
    Cl=None
    if ok:
      for A,C,F in loop_poses(o,a,c,d,turns,span,br):
        if inside(F,o) or dist_pt_poly(F,o)<0.05: ok=False; why='flap hits O'; break
        if inside(F,LIP) or dist_pt_poly(F,LIP)<LIPC: ok=False; why='flap at lip'; break
        if inside(wing,A) or inside(wing,C): ok=False; why='pin in wing'; break
        if not oin and seg_hits_poly(o,A,wing): ok=False; why='link cuts wing'; break
        if not ain and seg_hits_poly(o,A,F): ok=False; why='link cuts flap'; break
        Cl=C
      if ok:
        if seg_hits_poly(c,Cl,wing): ok=False; why='track cuts wing'
    if ok:
      for A,C,F in loop_poses(o,a,c,d,turns,span,br):
        if not cin and seg_hits_poly(c,Cl,F): ok=False; why='flap hits track'; break
    stats[why]=stats.get(why,0)+1
    if ok:
        print('%.1f%% mu %.0f d %d O %s A %s C %s Oinwing %s Ain %s Cin %s Cland %s turns %s'%(dep,mu,k,np.round(o,3),np.round(a,3),np.round(c,3),oin,ain,cin,np.round(Cl,3),np.round(np.degrees(turns),1)))
        shown+=1
        if shown>=12: break
print(stats)
