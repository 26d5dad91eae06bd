%
O0;00 (BRACKET - CONTOUR, BOLT CIRCLE(drilling pattern in a Mac ANDr