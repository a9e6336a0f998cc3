; Our fastest affine loops: fatmap2's 8:16 core unrolled and entered part-way (the first block
; starts part-way, the destination moved back to match), so no pixel pays for a loop counter; one
; pointer to the 64 KiB-aligned texture whose bh:bl is the texel's v:u.
;   fast_run_loop_asm (fast-affine):     a run of rows, the edge walking included (twin: fast_run_loop):
;                                        pixels in pairs, al then ah, one word store a pair, eight
;                                        pairs a block, an odd last pixel alone;
;   fast_column_loop_asm (fast-columns): one Mode X column (twin: fast_column_loop): eight pixels a
;                                        block, each stored alone (they lie 80 bytes apart).
;   The core, its registers and its blocks: asm/core816.inc; [esp]: the entry point.

bits 32

%include "fast.inc"
%include "loop.inc"
%include "core816.inc"

section .text

; fast_column_loop_asm: one column, pixels MODEX_ROW_BYTES apart; the map mask is the caller's.
global fast_column_loop_asm
fast_column_loop_asm:
    LOOP_ENTER 4
    mov eax, LOOP_ARG(4)
    mov ecx, [eax + FCOL_count]
    test ecx, ecx
    jle .done
    mov edi, [eax + FCOL_dst]
    mov edx, ecx
    neg edx
    and edx, 7                          ; the first block starts at pixel j = (-count) mod 8
    imul ebx, edx, MODEX_ROW_BYTES
    sub edi, ebx                        ; so that pixel j of that block is the first pixel
    mov edx, [column_entries + edx * 4]
    mov [esp], edx
    add ecx, 7
    shr ecx, 3                          ; blocks, the first one partial
    mov ebx, [eax + FCOL_texture]
    mov bl, [eax + FCOL_u_16_16 + 2]
    mov bh, [eax + FCOL_v_16_16 + 2]
    mov edx, [eax + FCOL_v_16_16]
    shl edx, 16
    mov dl, [eax + FCOL_du_16_16 + 2]
    mov dh, [eax + FCOL_dv_16_16 + 2]
    mov esi, [eax + FCOL_du_16_16]
    shl esi, 16
    mov ebp, [eax + FCOL_dv_16_16]
    shl ebp, 16
    mov eax, [eax + FCOL_u_16_16]
    shl eax, 16
    jmp [esp]
    BLOCKS MODEX_ROW_BYTES
.done:
    LOOP_LEAVE 4

; fast_run_loop_asm: a run of fast-affine's rows (twin: fast_run_loop): both edge bounds stepped in place,
; each row's span drawn by the same unrolled core. The core keeps its registers from row to row where
; it can (esi and ebp hold the fraction steps throughout); the rest of the row state lives in the frame.
L_ARGS    equ 0
L_ENTRY   equ 4
L_LINES   equ 8
L_ROW     equ 12
L_U       equ 16
L_V       equ 20
L_TEXTURE equ 24
L_STEPS   equ 28                        ; a word: du whole, dv whole
L_ODD     equ 32                        ; 1: the row's pixels are odd, the last drawn alone
L_FRAME   equ 36

; steps bound [%1] one line: q += dq, r += dr, and one more on q when r reaches d. Clobbers ebx.
%macro STEP_BOUND 1
    mov ebx, [%1 + BOUND_dq]
    add [%1 + BOUND_q], ebx
    mov ebx, [%1 + BOUND_r]
    add ebx, [%1 + BOUND_dr]
    cmp ebx, [%1 + BOUND_d]
    jb %%stepped
    sub ebx, [%1 + BOUND_d]
    inc dword [%1 + BOUND_q]
%%stepped:
    mov [%1 + BOUND_r], ebx
%endmacro

global fast_run_loop_asm
fast_run_loop_asm:
    LOOP_ENTER L_FRAME
    mov ecx, LOOP_ARG(L_FRAME)
    mov eax, [ecx + RUN_lines]
    test eax, eax
    jle .done
    mov [esp + L_ARGS], ecx
    mov [esp + L_LINES], eax
    mov eax, [ecx + RUN_row]
    mov [esp + L_ROW], eax
    mov eax, [ecx + RUN_u_16_16]
    mov [esp + L_U], eax
    mov eax, [ecx + RUN_v_16_16]
    mov [esp + L_V], eax
    mov eax, [ecx + RUN_texture]
    mov [esp + L_TEXTURE], eax
    mov al, [ecx + RUN_du_16_16 + 2]
    mov ah, [ecx + RUN_dv_16_16 + 2]
    mov [esp + L_STEPS], ax
    mov esi, [ecx + RUN_du_16_16]
    shl esi, 16                         ; du fraction
    mov ebp, [ecx + RUN_dv_16_16]
    shl ebp, 16                         ; dv fraction
.row:
    mov ecx, [esp + L_ARGS]
    mov edx, [ecx + RUN_lower]
    mov eax, [edx + BOUND_q]            ; the first pixel, before the clip
    STEP_BOUND edx
    cmp eax, [ecx + RUN_clip_lo]
    jge .lo_inside
    mov eax, [ecx + RUN_clip_lo]
.lo_inside:
    mov edx, [ecx + RUN_upper]
    mov edi, [edx + BOUND_q]            ; the last pixel
    STEP_BOUND edx
    cmp edi, [ecx + RUN_clip_hi]
    jle .hi_inside
    mov edi, [ecx + RUN_clip_hi]
.hi_inside:
    sub edi, eax
    jl .next_row                        ; nothing on this row
    inc edi                             ; the span's pixels
    mov edx, [ecx + RUN_tally]
    inc dword [edx]
    add [edx + 4], edi
    mov ebx, eax
    imul ebx, [ecx + RUN_du_16_16]
    add ebx, [esp + L_U]                ; u at the first pixel
    mov edx, eax
    imul edx, [ecx + RUN_dv_16_16]
    add edx, [esp + L_V]                ; v at the first pixel
    add eax, [esp + L_ROW]              ; its address
    mov ecx, edi
    and edi, 1
    mov [esp + L_ODD], edi              ; an odd pixel, drawn after the pairs
    shr ecx, 1                          ; pairs
    PAIR_ENTRY eax, edi, run_entries    ; blocks, the first one partial; 0 (ZF): no pair, one pixel
    mov edi, eax
    mov eax, ebx                        ; (mov and ror leave ZF as shr set it)
    ror eax, 16                         ; u: fraction in the high half, whole in al
    ror edx, 16                         ; v: the same, whole in dl
    mov ebx, [esp + L_TEXTURE]
    mov bl, al
    mov bh, dl
    mov dx, [esp + L_STEPS]
    jz .odd_pixel
    PAIRS_AND_ODD .next_row
.next_row:
    mov ecx, [esp + L_ARGS]
    mov eax, [ecx + RUN_u_row_16_16]
    add [esp + L_U], eax
    mov eax, [ecx + RUN_v_row_16_16]
    add [esp + L_V], eax
    mov eax, [ecx + RUN_pitch]
    add [esp + L_ROW], eax
    dec dword [esp + L_LINES]
    jnz .row
.done:
    LOOP_LEAVE L_FRAME

section .rodata
align 4
column_entries:
    dd fast_column_loop_asm.e0, fast_column_loop_asm.e1, fast_column_loop_asm.e2, fast_column_loop_asm.e3
    dd fast_column_loop_asm.e4, fast_column_loop_asm.e5, fast_column_loop_asm.e6, fast_column_loop_asm.e7
run_entries:
    dd fast_run_loop_asm.e0, fast_run_loop_asm.e1, fast_run_loop_asm.e2, fast_run_loop_asm.e3
    dd fast_run_loop_asm.e4, fast_run_loop_asm.e5, fast_run_loop_asm.e6, fast_run_loop_asm.e7

section .text

; triangle_rows_asm: a small triangle's row bounds (twin: triangle_rows, kernel/core/walk.cpp), for
; EdgeWalker's 32-bit build: each edge across the rows gives the bound of the rows whose centre lies
; within its extent, floor(m / d) with its remainder and step, m and the step from the edge function
; at the pixel corner (origin_x, origin_y); one IDIV for a quotient and its remainder. Returns 1, or
; 0 with nothing written where an edge lies along a row (dy = 0: the C++ build cuts rows with it).
T_OMAJ    equ 0                         ; origin_y * 256
T_OMIN    equ 4                         ; origin_x * 256
T_FIRST   equ 8                         ; the rows, relative to origin_y
T_LAST    equ 12
T_NLOWER  equ 16                        ; bounds in each chain so far
T_NUPPER  equ 20
T_FRAME   equ 24

; one edge: esi the edges, ebp the block
%macro TRI_EDGE 1
%define E(f) [esi + (%1) * EDGE_SIZE + EDGE_ %+ f]
    mov eax, E(py)
    sub eax, [esp + T_OMAJ]             ; pmaj: the start, relative
    mov ebx, E(dy)                      ; dmaj (not 0)
    lea ecx, [eax + ebx]                ; the end
    mov edx, eax
    cmp ecx, eax
    cmovl edx, ecx                      ; the top
    cmovl ecx, eax                      ; the bottom
    add edx, 127
    sar edx, 8                          ; lo: the first row whose centre is at or below the top
    sub ecx, 128
    sar ecx, 8                          ; hi: the last row whose centre is at or above the bottom
    mov edi, [esp + T_FIRST]
    cmp edx, edi
    cmovl edx, edi
    mov edi, [esp + T_LAST]
    cmp ecx, edi
    cmovg ecx, edi
    cmp edx, ecx
    jg %%skip                           ; no row's centre within its extent
    ; its place: going up (dy < 0) a lower bound, down an upper one
    test ebx, ebx
    js %%lower
    mov edi, [esp + T_NUPPER]
    inc dword [esp + T_NUPPER]
    imul edi, edi, BOUND_SIZE
    add edi, [ebp + TRI_upper]
    jmp %%placed
%%lower:
    mov edi, [esp + T_NLOWER]
    inc dword [esp + T_NLOWER]
    imul edi, edi, BOUND_SIZE
    add edi, [ebp + TRI_lower]
%%placed:
    push edx
    add edx, [ebp + TRI_origin_y]
    mov [edi + BOUND_first], edx
    add ecx, [ebp + TRI_origin_y]
    mov [edi + BOUND_last], ecx
    pop edx
    ; B at row lo: dmin * (lo * 256 + 128 - pmaj) - dmaj * (128 - pmin)
    shl edx, 8
    add edx, 128
    sub edx, eax
    imul edx, E(dx)
    mov eax, 128 + 0
    add eax, [esp + T_OMIN]
    sub eax, E(px)                      ; 128 - pmin
    imul eax, ebx
    sub edx, eax                        ; B
    mov ecx, E(dx)
    shl ecx, 8                          ; C = dmin * 256
    test ebx, ebx
    js %%below
    shl ebx, 8                          ; upper: d = dmaj * 256, m = B - t, step C
    sub edx, E(threshold)
    jmp %%divide
%%below:
    neg ebx
    shl ebx, 8                          ; lower: d = -dmaj * 256, m = t - B + d - 1, step -C
    neg edx
    add edx, E(threshold)
    lea edx, [edx + ebx - 1]
    neg ecx
%%divide:
    mov [edi + BOUND_d], ebx
    mov eax, edx
    cdq
    idiv ebx                            ; truncated: a negative remainder steps the quotient down
    test edx, edx
    jns %%q
    dec eax
    add edx, ebx
%%q:
    add eax, [ebp + TRI_origin_x]
    mov [edi + BOUND_q], eax
    mov [edi + BOUND_r], edx
    mov eax, ecx
    cdq
    idiv ebx
    test edx, edx
    jns %%dq
    dec eax
    add edx, ebx
%%dq:
    mov [edi + BOUND_dq], eax
    mov [edi + BOUND_dr], edx
%%skip:
%undef E
%endmacro

; a chain of two in order of first row (a tie keeps their order), then its sentinel: never live,
; never binding (q = %2)
%macro TRI_SEAL 3
    mov edi, [ebp + %1]
    mov ecx, [esp + %2]
    cmp ecx, 2
    jne %%sentinel
    mov eax, [edi + BOUND_first]
    cmp eax, [edi + BOUND_SIZE + BOUND_first]
    jle %%sentinel
%assign off 0
%rep BOUND_SIZE / 4
    mov eax, [edi + off]
    mov edx, [edi + BOUND_SIZE + off]
    mov [edi + off], edx
    mov [edi + BOUND_SIZE + off], eax
%assign off off + 4
%endrep
%%sentinel:
    imul ecx, ecx, BOUND_SIZE
    add edi, ecx
    mov dword [edi + BOUND_first], 0x7FFFFFFF
    mov dword [edi + BOUND_last], 0x7FFFFFFF
    mov dword [edi + BOUND_q], %3
    mov dword [edi + BOUND_dq], 0
    mov dword [edi + BOUND_r], 0
    mov dword [edi + BOUND_dr], 0
    mov dword [edi + BOUND_d], 1
%endmacro

global triangle_rows_asm
triangle_rows_asm:
    LOOP_ENTER T_FRAME
    mov ebp, LOOP_ARG(T_FRAME)
    mov esi, [ebp + TRI_edges]
    xor eax, eax
    cmp [esi + EDGE_dy], eax
    je .done
    cmp [esi + EDGE_SIZE + EDGE_dy], eax
    je .done
    cmp [esi + 2 * EDGE_SIZE + EDGE_dy], eax
    je .done
    mov [esp + T_NLOWER], eax
    mov [esp + T_NUPPER], eax
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
    TRI_EDGE 0
    TRI_EDGE 1
    TRI_EDGE 2
    TRI_SEAL TRI_lower, T_NLOWER, 0x80000000
    TRI_SEAL TRI_upper, T_NUPPER, 0x7FFFFFFF
    mov eax, 1
.done:
    LOOP_LEAVE T_FRAME
