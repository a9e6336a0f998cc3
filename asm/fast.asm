; Our fastest affine loops: fatmap2's 8:16 core unrolled and entered part-way (the first block
; starts part-way, the destination moved back to match), so no pixel pays for a loop counter; one
; pointer to the 64 KiB-aligned texture whose bh:bl is the texel's v:u.
;   fast_run_loop_asm (fast-affine):     a run of rows, the edge walking included (twin: fast_run_loop):
;                                        pixels in pairs, al then ah, one word store a pair, eight
;                                        pairs a block, an odd last pixel alone; on a doubled copy
;                                        (textures above 256 a side) a texel pointer stepped by
;                                        the fractions' carries, as Quake's d_draw16.s steps its own;
;   fast_table_loop_asm (fast-table):    the same rows, each span read through the polygon's offset
;                                        table (twin: fast_table_loop): two loads a pixel, one word
;                                        store a pair, sixteen pairs a block; from the doubled copy;
;   fast_column_run_asm (fast-columns):  a run of Mode X columns, the edge walking included (twin:
;                                        fast_column_run): eight pixels a block, each stored alone
;                                        (they lie 80 bytes apart); on a doubled copy the texel
;                                        pointer a pixel at a time;
;   fast_table_column_loop_asm (fast-table-columns): one column through the offset table (twin:
;                                        fast_table_column_loop): a load, a load and a store a pixel.
;   The core, its registers and its blocks: asm/core816.inc; [esp]: the entry point.

bits 32

%include "fast.inc"
%include "walk.inc"
%include "surface.inc"
%include "loop.inc"
%include "core816.inc"

section .text

; The doubled copy's texel pointer (fast-affine's rows, fast-columns' column): from the block %1
; (its fields %2_du_16_16, %2_dv_16_16 and %2_block_pitch), ebp the du fraction and the frame's
; slots %3 the dv fraction, %4 the pointer's step with a carry from v (a row more) and %4 + 4
; without; %5 a scratch register (edx is lost too).
%macro DOUBLED_STEPS 5
    mov ebp, [%1 + %2_du_16_16]
    shl ebp, 16                         ; du fraction
    mov %5, [%1 + %2_dv_16_16]
    shl %5, 16
    mov [esp + %3], %5                  ; dv fraction
    mov %5, [%1 + %2_dv_16_16]
    sar %5, 16
    imul %5, [%1 + %2_block_pitch]
    mov edx, [%1 + %2_du_16_16]
    sar edx, 16
    add %5, edx                         ; dv's whole rows and du's whole columns
    mov [esp + %4 + 4], %5
    add %5, [%1 + %2_block_pitch]
    mov [esp + %4], %5
%endmacro
; The computed entry into blocks of eight column pixels for ecx pixels from edi: the first block
; starts at pixel j = (-pixels) mod 8 (left in edx), so the destination moves j rows back and
; [esp + %2] takes entry j of the table %1; ecx: the blocks, the first one partial (ebx clobbered).
%macro COLUMN_BLOCKS_ENTRY 2
    mov edx, ecx
    neg edx
    and edx, 7
    imul ebx, edx, MODEX_ROW_BYTES
    sub edi, ebx
    mov ebx, [%1 + edx * 4]
    mov [esp + %2], ebx
    add ecx, 7
    shr ecx, 3
%endmacro
; The column loop's entry: a frame of the entry alone, the block (eax), its pixel count (ecx) and
; destination (edi) from the fields %1_count and %1_dst (.done: no pixels); then the computed entry
; through the table %2 into [esp].
%macro COLUMN_ENTER 2
    LOOP_ENTER 4
    mov eax, LOOP_ARG(4)
    mov ecx, [eax + %1_count]
    test ecx, ecx
    jle .done
    mov edi, [eax + %1_dst]
    COLUMN_BLOCKS_ENTRY %2, 0
%endmacro

; A column's pixels on a doubled copy: blocks of eight, the frame's slot %3 of them, entered at .e0
; to .e7 (%1 and %2: the slots DOUBLED_STEP reads).
%macro DCOL_PIXEL 3                     ; %1: the pixel's offset within the block
    mov al, [esi]
    DOUBLED_STEP %2, %3
    mov [edi + %1], al
%endmacro
%macro DCOL_BLOCKS 3
.block:
.e0: DCOL_PIXEL 0, %1, %2
.e1: DCOL_PIXEL MODEX_ROW_BYTES, %1, %2
.e2: DCOL_PIXEL 2 * MODEX_ROW_BYTES, %1, %2
.e3: DCOL_PIXEL 3 * MODEX_ROW_BYTES, %1, %2
.e4: DCOL_PIXEL 4 * MODEX_ROW_BYTES, %1, %2
.e5: DCOL_PIXEL 5 * MODEX_ROW_BYTES, %1, %2
.e6: DCOL_PIXEL 6 * MODEX_ROW_BYTES, %1, %2
.e7: DCOL_PIXEL 7 * MODEX_ROW_BYTES, %1, %2
    add edi, 8 * MODEX_ROW_BYTES
    dec dword [esp + %3]
    jnz .block
%endmacro

; fast_table_column_loop_asm: one Mode X column through the polygon's offset table (twin:
; fast_table_column_loop): pixel n is [esi + table[n]], eight pixels a block, each stored alone.
%macro TCOL_PIXEL 1                     ; %1: the pixel within the block
    mov ebx, [ebp + 4 * %1]
    mov al, [esi + ebx]
    mov [edi + %1 * MODEX_ROW_BYTES], al
%endmacro

global fast_table_column_loop_asm
fast_table_column_loop_asm:
    COLUMN_ENTER TCOL, table_column_entries
    mov esi, [eax + TCOL_source]
    mov ebp, [eax + TCOL_table]
    lea ebx, [edx * 4]
    sub ebp, ebx                        ; the table j entries back, as the destination
    jmp [esp]
.block:
.e0: TCOL_PIXEL 0
.e1: TCOL_PIXEL 1
.e2: TCOL_PIXEL 2
.e3: TCOL_PIXEL 3
.e4: TCOL_PIXEL 4
.e5: TCOL_PIXEL 5
.e6: TCOL_PIXEL 6
.e7: TCOL_PIXEL 7
    add ebp, 32
    add edi, 8 * MODEX_ROW_BYTES
    dec ecx
    jnz .block
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
L_LOWER   equ 36                        ; the run's bounds
L_UPPER   equ 40
L_NEXT    equ 44                        ; the next run's rows (0 or less: none, or taken)
L_DVF     equ 48                        ; on a doubled copy: dv fraction (high half)
L_DSTEP   equ 52                        ; the pointer's step a pixel, with a carry from v (a row more)
L_DSTEP0  equ 56                        ; and without
L_BLOCKS  equ 60                        ; the blocks left
L_FRAME   equ 64

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

; The 8:16 core's steps from the block (ecx; %1 its prefix) for a whole call: the wholes of du and
; dv into the frame's word at L_STEPS, their fractions into esi and ebp.
%macro CORE_STEPS 1
    mov al, [ecx + %1_du_16_16 + 2]
    mov ah, [ecx + %1_dv_16_16 + 2]
    mov [esp + L_STEPS], ax
    mov esi, [ecx + %1_du_16_16]
    shl esi, 16                         ; du fraction
    mov ebp, [ecx + %1_dv_16_16]
    shl ebp, 16                         ; dv fraction
%endmacro
; The 8:16 core's start from u (ebx) and v (edx), 16.16 at the first pixel: eax and edx their
; fractions in the high halves, ebx the texture with v's and u's wholes in bh and bl, dx the steps'
; wholes (L_STEPS). ZF is left as it was (mov and ror do not write it).
%macro CORE_START 0
    mov eax, ebx
    ror eax, 16                         ; u: fraction in the high half, whole in al
    ror edx, 16                         ; v: the same, whole in dl
    mov ebx, [esp + L_TEXTURE]
    mov bl, al
    mov bh, dl
    mov dx, [esp + L_STEPS]
%endmacro

; The run loops' entry (rows by default; %1 the block's prefix, %2 the frame's bytes, %3 the field
; of the first line and %4 its slot): the frame, the block's line state copied into it (.done: no
; lines).
%macro RUN_ENTER 0-4 RUN, L_FRAME, RUN_row, L_ROW
    LOOP_ENTER %2
    mov ecx, LOOP_ARG(%2)
    mov eax, [ecx + %1_lines]
    test eax, eax
    jle .done
    mov [esp + L_ARGS], ecx
    mov [esp + L_LINES], eax
    FRAME_COPY ecx, %1_lower, L_LOWER, %1_upper, L_UPPER, %1_next_lines, L_NEXT, %3, %4, %1_u_16_16, L_U, %1_v_16_16, L_V
%endmacro

; A row's start (ecx: the block, as RUN_ENTER and ROW_TAIL leave it; %2 its prefix, rows' by
; default; a column's the same): both bounds stepped, the span clipped (%1 = 1; 0: a run the block
; says lies inside the clip, RUN_inside) (.next_row where it is empty) and tallied; out: eax the
; first pixel's x, edi the span's pixels.
%macro ROW_HEAD 1-2 RUN
    mov edx, [esp + L_LOWER]
    mov eax, [edx + BOUND_q]            ; the first pixel, before the clip
    STEP_BOUND edx
%if %1
    cmp eax, [ecx + %2_clip_lo]
    jge %%lo_inside
    mov eax, [ecx + %2_clip_lo]
%%lo_inside:
%endif
    mov edx, [esp + L_UPPER]
    mov edi, [edx + BOUND_q]            ; the last pixel
    STEP_BOUND edx
%if %1
    cmp edi, [ecx + %2_clip_hi]
    jle %%hi_inside
    mov edi, [ecx + %2_clip_hi]
%%hi_inside:
%endif
    sub edi, eax
    jl .next_row                        ; nothing on this row
    inc edi                             ; the span's pixels
    mov edx, [ecx + %2_tally]
    inc dword [edx]
    add [edx + 4], edi
%endmacro

; After ROW_HEAD, fast-affine's: ebx and edx u and v (16.16) at the first pixel, eax its address.
%macro ROW_UV 0
    mov ebx, eax
    imul ebx, [ecx + RUN_du_16_16]
    add ebx, [esp + L_U]                ; u at the first pixel
    mov edx, eax
    imul edx, [ecx + RUN_dv_16_16]
    add edx, [esp + L_V]                ; v at the first pixel
    add eax, [esp + L_ROW]              ; its address
%endmacro

; The next row: u, v and the row's address advance; then RUN_NEXT.
%macro ROW_TAIL 0
    mov ecx, [esp + L_ARGS]
    mov eax, [ecx + RUN_u_row_16_16]
    add [esp + L_U], eax
    mov eax, [ecx + RUN_v_row_16_16]
    add [esp + L_V], eax
    mov eax, [ecx + RUN_pitch]
    add [esp + L_ROW], eax
    RUN_NEXT
%endmacro
; .row while lines are left, then the next run's lines once where the block (ecx; %1 its prefix,
; rows' by default) has one.
%macro RUN_NEXT 0-1 RUN
    dec dword [esp + L_LINES]
    jnz .row
    mov eax, [esp + L_NEXT]
    test eax, eax
    jle .done
    mov [esp + L_LINES], eax
    mov dword [esp + L_NEXT], 0
    mov eax, [ecx + %1_next_lower]
    mov [esp + L_LOWER], eax
    mov eax, [ecx + %1_next_upper]
    mov [esp + L_UPPER], eax
    jmp .row
%endmacro

; fast_run_loop_asm's rows from .row, clipped (%1 = 1) or not (0), the pairs entered through the
; table %2; then the frame freed.
%macro RUN_ROWS 2
.row:
    ROW_HEAD %1
    ROW_UV
    mov ecx, edi
    and edi, 1
    mov [esp + L_ODD], edi              ; an odd pixel, drawn after the pairs
    shr ecx, 1                          ; pairs
    PAIR_ENTRY eax, edi, %2             ; blocks, the first one partial; 0 (ZF): no pair, one pixel
    mov edi, eax
    CORE_START                          ; (leaves ZF as shr set it)
    jz .odd_pixel
    PAIRS_AND_ODD .next_row
.next_row:
    ROW_TAIL
.done:
    LOOP_LEAVE L_FRAME
%endmacro

global fast_run_loop_asm
fast_run_loop_asm:
    RUN_ENTER
    mov eax, [ecx + RUN_texture]
    mov [esp + L_TEXTURE], eax
    cmp dword [ecx + RUN_source], SOURCE_TILED_BLOCK
    jne fast_run_doubled
    CORE_STEPS RUN
    cmp dword [ecx + RUN_inside], 0
    jne fast_run_inside.row
    RUN_ROWS 1, run_entries
; the same rows of a run inside the clip, without its compares (a label of its own: its own .row,
; .block and entries)
fast_run_inside:
    RUN_ROWS 0, run_inside_entries

; fast_run_loop_asm's rows on a doubled copy (RUN_source DOUBLED_COPY: textures above 256 a side): the same
; rows, the span's texels read through a pointer into the copy that steps as Quake's d_draw16.s
; steps its own (no wrap: u and v come less their window's corner, and the window fits the copy):
; v's carry picks a step with a row more or without, u's adds one by adc; pixels in pairs, al then
; ah, one word store a pair, eight pairs a block, an odd last pixel alone.
; the doubled copy's rows from .row, clipped (%1 = 1) or not (0), the pairs entered through the
; table %2; then the frame freed.
%macro DOUBLED_ROWS 2
.row:
    ROW_HEAD %1
    ROW_UV
    DOUBLED_TEXEL edx, ebx, [ecx + RUN_block_pitch], [esp + L_TEXTURE], ecx
    shl ebx, 16                         ; u fraction
    shl edx, 16                         ; v fraction
    mov ecx, edi
    and edi, 1
    mov [esp + L_ODD], edi              ; an odd pixel, drawn after the pairs
    shr ecx, 1                          ; pairs
    PAIR_ENTRY eax, edi, %2             ; blocks, the first one partial; 0 (ZF): no pair, one pixel
    mov [esp + L_BLOCKS], ecx
    mov edi, eax                        ; (the movs leave ZF as shr set it)
    jz .odd_pixel
    jmp [esp + L_ENTRY]
    DPAIR_BLOCKS
.odd_pixel:                             ; edi: just past the pairs
    cmp dword [esp + L_ODD], 0
    je .next_row
    mov al, [esi]
    mov [edi], al
.next_row:
    ROW_TAIL
.done:
    LOOP_LEAVE L_FRAME
%endmacro

fast_run_doubled:
    DOUBLED_STEPS ecx, RUN, L_DVF, L_DSTEP, eax
    cmp dword [ecx + RUN_inside], 0
    jne fast_run_doubled_inside.row
    DOUBLED_ROWS 1, run_doubled_entries
fast_run_doubled_inside:
    DOUBLED_ROWS 0, run_doubled_inside_entries

; fast_column_run_asm: a run of fast-columns' columns on the tiled block (twin: fast_column_run):
; walked as fast_run_loop_asm walks its rows (RUN_ENTER, ROW_HEAD, RUN_NEXT; the rows' frame, and
; the column's own state after it), each column's span drawn by the 8:16 column core (BLOCKS, eight
; pixels a block, entered part-way) into the Mode X planar target, its plane selected first through
; the target's select_plane where it has one (the VGA's map mask: a cdecl call, which keeps ebx,
; esi, edi and ebp). esi and ebp hold the fraction steps for the whole call.
K_X       equ L_FRAME                   ; the column
K_DU      equ L_FRAME + 4               ; u's and v's steps down a column
K_DV      equ L_FRAME + 8
K_BASE    equ L_FRAME + 12              ; the target's
K_PLANE   equ L_FRAME + 16              ; bytes from a plane to the next (0: the VGA's map mask picks it)
K_PITCH   equ L_FRAME + 20              ; the doubled copy's bytes a row (0: the tiled block)
K_FRAME   equ L_FRAME + 24
; The columns from .row: %1 tiled (the 8:16 column core) or doubled (the copy's texel pointer), the
; first block entered through the table %2; then the frame freed.
%macro COLUMN_RUN 2
.row:                                   ; a column; ecx: the block
    ROW_HEAD 1, CRUN
    mov ebx, [ecx + CRUN_target]
    cmp dword [ebx + TGT_select_plane], 0
    je .selected
    push eax                            ; (the first pixel; edi is kept by the call)
    mov edx, [esp + 4 + K_X]
    and edx, 3
    push edx                            ; the plane
    push dword [ebx + TGT_ctx]
    call [ebx + TGT_select_plane]
    add esp, 8
    pop eax
.selected:                              ; eax: the first pixel's row, edi: the pixels
    mov ecx, edi
    mov edx, [esp + K_X]
    mov ebx, edx
    and edx, 3
    imul edx, [esp + K_PLANE]
    sar ebx, 2
    add edx, ebx
    add edx, [esp + K_BASE]             ; the column's row 0
    lea ebx, [eax + eax * 4]
    shl ebx, 4                          ; the first pixel's row * 80
    lea edi, [edx + ebx]                ; its address
    COLUMN_BLOCKS_ENTRY %2, L_ENTRY
    mov ebx, eax
    imul ebx, [esp + K_DU]
    add ebx, [esp + L_U]                ; u at the first pixel
    imul eax, [esp + K_DV]
    add eax, [esp + L_V]
    mov edx, eax                        ; v at the first pixel
%ifidn %1, tiled
    CORE_START
    jmp [esp + L_ENTRY]
    BLOCKS MODEX_ROW_BYTES
%else
    mov [esp + L_BLOCKS], ecx
    DOUBLED_TEXEL edx, ebx, [esp + K_PITCH], [esp + L_TEXTURE], ecx
    shl ebx, 16                         ; u fraction
    shl edx, 16                         ; v fraction
    jmp [esp + L_ENTRY]
    DCOL_BLOCKS L_DVF, L_DSTEP0, L_BLOCKS
%endif
.next_row:                              ; the next column
    mov ecx, [esp + L_ARGS]
    mov eax, [ecx + CRUN_u_column_16_16]
    add [esp + L_U], eax
    mov eax, [ecx + CRUN_v_column_16_16]
    add [esp + L_V], eax
    inc dword [esp + K_X]
    RUN_NEXT CRUN
.done:
    LOOP_LEAVE K_FRAME
%endmacro

global fast_column_run_asm
fast_column_run_asm:
    RUN_ENTER CRUN, K_FRAME, CRUN_x, K_X
    FRAME_COPY ecx, CRUN_du_16_16, K_DU, CRUN_dv_16_16, K_DV, CRUN_texture, L_TEXTURE, CRUN_block_pitch, K_PITCH
    mov edx, [ecx + CRUN_target]
    FRAME_COPY edx, TGT_base, K_BASE, TGT_plane_bytes, K_PLANE
    cmp dword [ecx + CRUN_block_pitch], 0
    jne fast_column_run_doubled
    CORE_STEPS CRUN
    COLUMN_RUN tiled, column_run_entries
; on a doubled copy (CRUN_block_pitch its pitch): ebp the du fraction, the frame the pointer's steps
fast_column_run_doubled:
    DOUBLED_STEPS ecx, CRUN, L_DVF, L_DSTEP, eax
    COLUMN_RUN doubled, column_run_doubled_entries

; fast_table_loop_asm: fast-table's rows (twin: fast_table_loop), walked as fast_run_loop_asm walks
; them, pixel x of a row read at the row's first texel + table[x]: an odd span's first pixel alone,
; then pairs, sixteen a block. A pair comes in with its offsets loaded, stores its texels as bytes and
; loads the next pair's offsets into registers its reads are done with (no AGI; docs/cycles.md, "Our
; loops against the goals"); the last pair's loads fall inside the table's room, never read through.
;   esi: the row's first texel   ebp, edi: the block's offsets and pixels (no index register)
;   ecx: the blocks left   ebx, edx: offsets   bl, al: texels
%macro TPAIR 1                          ; %1: the pair within the block
    mov al, [esi + edx]
    mov edx, [ebp + 8 * %1 + 12]
    mov bl, [esi + ebx]
    mov [edi + 2 * %1 + 1], al
    mov [edi + 2 * %1], bl
    mov ebx, [ebp + 8 * %1 + 8]
%endmacro

; fast_table_loop_asm's rows from .row, clipped (%1 = 1) or not (0), the pairs entered through the
; table %2, from the doubled copy; then the frame freed.
%macro TABLE_ROWS 2
.row:
    ROW_HEAD %1
    ; (a dword from a value's whole, its high half: the masks, below 65536, keep the whole's bits)
    mov esi, [esp + L_V + 2]
    and esi, [ecx + RUN_v_mask]
    imul esi, [ecx + RUN_block_pitch]   ; (v whole & v_mask) * pitch
    mov ebx, [esp + L_U + 2]
    and ebx, [ecx + RUN_u_mask]
    add esi, ebx
    add esi, [ecx + RUN_texture]        ; the texel of the table's first pixel
    mov ebp, [ecx + RUN_table]
    lea ebp, [ebp + eax * 4]            ; the span's first pixel's offset
    add eax, [esp + L_ROW]              ; its address
    test edi, 1
    jz .even
    mov ebx, [ebp]                      ; an odd span's first pixel alone
    mov bl, [esi + ebx]
    mov [eax], bl
    inc eax
    add ebp, 4
.even:
    mov ecx, edi
    shr ecx, 1                          ; pairs (ZF: none)
    jz .next_row
    mov edi, eax                        ; the first pair's pixels
    mov ebx, [ebp]                      ; and its offsets, as TPAIR takes them
    mov eax, [ebp + 4]
    mov edx, ecx
    neg edx
    and edx, 15                         ; the first block starts at pair j = (-pairs) mod 16
    sub edi, edx
    sub edi, edx                        ; the destination and the offsets j pairs back
    neg edx
    lea ebp, [ebp + edx * 8]
    neg edx
    mov edx, [%2 + edx * 4]
    mov [esp + L_ENTRY], edx
    mov edx, eax
    add ecx, 15
    shr ecx, 4                          ; the blocks
    jmp [esp + L_ENTRY]
.block:
.e0: TPAIR 0
.e1: TPAIR 1
.e2: TPAIR 2
.e3: TPAIR 3
.e4: TPAIR 4
.e5: TPAIR 5
.e6: TPAIR 6
.e7: TPAIR 7
.e8: TPAIR 8
.e9: TPAIR 9
.e10: TPAIR 10
.e11: TPAIR 11
.e12: TPAIR 12
.e13: TPAIR 13
.e14: TPAIR 14
.e15: TPAIR 15
    add ebp, 128
    add edi, 32
    dec ecx
    jnz .block
.next_row:
    ROW_TAIL
.done:
    LOOP_LEAVE L_FRAME
%endmacro

global fast_table_loop_asm
fast_table_loop_asm:
    RUN_ENTER
    cmp dword [ecx + RUN_inside], 0
    jne fast_table_inside.row
    TABLE_ROWS 1, table_entries
fast_table_inside:
    TABLE_ROWS 0, table_inside_entries

section .rodata
align 4
    ENTRIES column_run_entries, fast_column_run_asm, 8
    ENTRIES column_run_doubled_entries, fast_column_run_doubled, 8
    ENTRIES run_entries, fast_run_loop_asm, 8
    ENTRIES run_inside_entries, fast_run_inside, 8
    ENTRIES run_doubled_entries, fast_run_doubled, 8
    ENTRIES run_doubled_inside_entries, fast_run_doubled_inside, 8
    ENTRIES table_column_entries, fast_table_column_loop_asm, 8
    ENTRIES table_entries, fast_table_loop_asm, 16
    ENTRIES table_inside_entries, fast_table_inside, 16
