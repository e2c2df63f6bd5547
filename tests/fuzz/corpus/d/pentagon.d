# a pentagon without a header

0 0 0
1 0 0
1.3 1 0
0.5 1.6 0
-0.3 1 0

5 1 2 3 4 5   # fan
