// shadow.frag: depth only; the colour is thrown away (the shadow map has no colour buffer).

void main() {}
