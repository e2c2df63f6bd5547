data 3 1
0 0 0
1 zero 0
0 1 0
3 1 2 3
