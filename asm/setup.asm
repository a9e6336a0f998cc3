; setup_triangle_affine_asm(const Vertex* in, PolygonSetup* out): setup_polygon's work on a triangle
; whose corners are in range (Input::InRange), affine planes only (PLANES_AFFINE), for the fast
; mappers (twin: the same call in C++, kernel/core/setup.cpp): the orientation, the edges with the
; top-left rule, the box, the u and v planes in x87 double arithmetic (53-bit precision, the
; kernel's), operation for operation as plane_through, and their 16.16 form as finish_setup makes
; it. Returns 1, or 0 with `out` in an unspecified state where C++ must do it: a repeated corner or
; no area (degenerate), or a value off its 32-bit path (a 16.16 step whose floor leaves int32,
; 32768 texels a pixel or more either way, an anchor value outside [0, 16384) texels).

bits 32

%include "setup.inc"
%include "loop.inc"
%include "triangle_setup.inc"

section .text

global setup_triangle_affine_asm
setup_triangle_affine_asm:
    LOOP_ENTER S_FRAME
    mov esi, LOOP_ARG(S_FRAME)          ; in
    mov ebp, [esp + S_FRAME + 24]       ; out
    SETUP_TRIANGLE
    mov eax, 1
    jmp .done
    SETUP_EXITS S_FRAME

section .rodata
align 8
setup_2_24:     dq 16777216.0
setup_65536:    dq 65536.0
setup_half:     dq 0.5
setup_16384:    dq 16384.0
