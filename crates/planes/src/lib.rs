//! Support stations, mechanism planes with skew correction, station frames and section cuts. (Being filled: issue 3.)
