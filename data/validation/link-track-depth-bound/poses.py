import json, numpy as np
def load(path):
    r=json.load(open(path)); s=r['stations'][0]
    syn=s['mechanism']['details']['synthesis']
    O=np.array(syn['link_pivot_m']); A=np.array(syn['link_flap_pivot_m']); C=np.array(syn['carriage_m'])
    d=np.array(syn['track_direction']); tr=syn['carriage_travel_m']; ph=syn['link_rotation_rad']
    poses=[]
    for t,p in zip(tr,ph):
        R=np.array([[np.cos(p),-np.sin(p)],[np.sin(p),np.cos(p)]])
        Ai=O+R@(A-O); Ci=C+d*t
        v0=C-A; v1=Ci-Ai
        th=np.arctan2(v0[0]*v1[1]-v0[1]*v1[0], v0@v1)
        Rf=np.array([[np.cos(th),-np.sin(th)],[np.sin(th),np.cos(th)]])
        tf=Ai-Rf@A
        poses.append((Rf,tf,th))
    secs=s['plane']['sections']
    polys={x['part_name']:[np.array(p) for p in x['polygons']] for x in secs}
    return poses,polys,s
if __name__=='__main__':
    import sys
    poses,polys,s=load(sys.argv[1])
    for R,t,th in poses: print(np.degrees(th), t)
    print(polys.keys())
