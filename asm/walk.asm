; triangle_rows_asm: a small triangle's row bounds (twin: triangle_rows, kernel/core/walk.cpp), for
; EdgeWalker's 32-bit build: each edge across the rows gives the bound of the rows whose centre lies
; within its extent, floor(m / d) with its remainder and step, m and the step from the edge function
; at the pixel corner (origin_x, origin_y); one IDIV for a quotient and its remainder. Returns 1, or
; 0 with nothing written where an edge lies along a row (dy = 0: the C++ build cuts rows with it).

bits 32

%include "walk.inc"
%include "setup.inc"
%include "loop.inc"
%include "triangle_rows.inc"

section .text

global triangle_rows_asm
triangle_rows_asm:
    LOOP_ENTER T_FRAME
    mov ebp, LOOP_ARG(T_FRAME)
    mov esi, [ebp + TRI_edges]
    mov eax, [ebp + TRI_lower]
    mov [esp + T_LOWER], eax
    mov eax, [ebp + TRI_upper]
    mov [esp + T_UPPER], eax
    mov eax, [ebp + TRI_origin_y]
    mov edx, [ebp + TRI_first]
    sub edx, eax
    mov [esp + T_FIRST], edx
    mov edx, [ebp + TRI_last]
    sub edx, eax
    mov [esp + T_LAST], edx
    shl eax, 8
    mov [esp + T_OMAJ], eax
    mov eax, [ebp + TRI_origin_x]
    shl eax, 8
    mov [esp + T_OMIN], eax
    TRI_ROWS .done, {[ebp + TRI_origin_x]}, {[ebp + TRI_origin_y]}, {mov edi, [ebp + TRI_lower]}, {mov edi, [ebp + TRI_upper]}
    mov eax, 1
.done:
    LOOP_LEAVE T_FRAME
