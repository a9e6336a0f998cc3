; fast_subdiv_loop_asm (fast-subdiv-N): one span, segment by segment; twin of
; kernel/mappers/fastsubdiv.cpp (fast_subdiv_loop), which it matches bit for bit. Each exact point
; in x87 as the twin computes it (53-bit precision, the same operations in the same order, the
; 64-bit conversion rounding to nearest), the steps between two points by their 32-bit difference,
; the pixels by the 8:16 core (asm/core816.inc), entered part-way as fast_run_loop_asm enters it:
; a row (stride 1) in pairs, one word store a pair; a column (any other stride) a pixel at a time,
; the destination moved by the stride from the frame after each store. A span of one or two pixels
; (fast_subdiv_short) stores its exact points' texels, without the frame or the core. On a texture's
; doubled copy (FSUB_texture null: sides above 256) the same segments step a texel pointer into the
; copy (the doubled core, asm/core816.inc), started afresh at each segment where its travel stays in
; the copy, and read the copy by masks where it does not (fast_subdiv_doubled_asm).

bits 32

%include "fastsubdiv.inc"
%include "loop.inc"
%include "core816.inc"

section .rodata
align 8
subpixel_one: dq 256.0                  ; SUBPIXEL_ONE: a pixel in subpixels
scale_16_16:  dq 65536.0

L_ARGS        equ 0
L_LEFT        equ 4                     ; pixels from the segment's first to the span's end
L_DST         equ 8                     ; the segment's first pixel's address
L_U0          equ 12                    ; 16.16 at the segment's first pixel
L_V0          equ 16
L_U1          equ 20                    ; qword: 16.16 at its next exact point (the low dword kept)
L_V1          equ 28                    ; qword
L_TEXTURE     equ 36
L_N           equ 40                    ; a full segment's pixels
L_SHIFT       equ 44                    ; log2 of them
L_FULL_ENTRY  equ 48                    ; a full segment's entry into the pairs
L_FULL_BLOCKS equ 52                    ; and its blocks
L_FULL_BACK   equ 56                    ; and how far its destination moves back (0 or less)
L_ENTRY       equ 60                    ; the last segment's entry
L_ODD         equ 64                    ; 1: an odd last pixel after the pairs (the last segment's)
L_LAST        equ 68                    ; the span's last pixel, the last segment's exact point
L_D           equ 72                    ; the last segment's divisor
L_SEG_X       equ 76                    ; qword: a full segment in subpixels, n * 256
L_STRIDE      equ 84                    ; bytes from a pixel to the next
L_SEG_BYTES   equ 88                    ; bytes from a full segment's first pixel to the next's
; on a doubled copy only (L_TEXTURE: its origin)
L_PITCH       equ 92                    ; the copy's bytes a row
L_UMASK       equ 96                    ; the sides less one
L_VMASK       equ 100
L_UNEG        equ 104                   ; the column a falling u starts a side further on: the width
L_VNEG        equ 108                   ; and a falling v's row: the height
L_UREACH      equ 112                   ; (the width + 6) in 16.16, then twice that: a segment's
L_VREACH      equ 120                   ; u and v travel less than the first (the height's for v)
L_DVF         equ 128                   ; the doubled core's: dv fraction
L_DSTEP       equ 132                   ; its pointer's step with v's carry
L_DSTEP0      equ 136                   ; and without
L_BLOCKS      equ 140                   ; the blocks left (the masked pixels left)
L_DU          equ 144                   ; the masked pixels' steps
L_DV          equ 148
L_FRAME       equ 152

section .text

; the exact point at x (st0, kept) into [esp + L_U1], [esp + L_V1] (or the two offsets given);
; ecx (or the register given third): the block
%macro POINT 0
    POINT_AT L_U1, L_V1
%endmacro
%macro POINT_AT 2-3 ecx
    fld qword [%3 + FSUB_g]
    fmul st0, st1
    fadd qword [%3 + FSUB_c]           ; q = c0 + g0 x
    fld qword [%3 + FSUB_g + 8]
    fmul st0, st2
    fadd qword [%3 + FSUB_c + 8]       ; pu
    fdiv st0, st1
    fmul qword [scale_16_16]
    fistp qword [esp + %1]              ; u in 16.16, nearest
    fld qword [%3 + FSUB_g + 16]
    fmul st0, st2
    fadd qword [%3 + FSUB_c + 16]      ; pv
    fdiv st0, st1
    fmul qword [scale_16_16]
    fistp qword [esp + %2]
    fstp st0                            ; q
%endmacro

; the texel of the 16.16 point at [esp + %1], [esp + %2] into %3; %4: the texture (64 KiB
; aligned; the block's by default, edx holding the block); ecx clobbered
%macro TEXEL_AT 3-4 [edx + FSUB_texture]
    movzx ecx, byte [esp + %1 + 2]      ; u whole
    mov ch, [esp + %2 + 2]              ; v whole
    add ecx, %4
    mov %3, [ecx]
%endmacro

; The doubled copy's texel of the 16.16 point at %1 (u) and %2 (v) into %3, by masks: %4 the
; v mask, %5 the pitch, %6 the u mask, %7 the origin (operands); ecx and ebx clobbered.
%macro MASKED_TEXEL 7
    mov ecx, %2
    shr ecx, 16
    and ecx, %4
    imul ecx, %5                        ; the row
    mov ebx, %1
    shr ebx, 16
    and ebx, %6
    add ecx, ebx                        ; and the column
    add ecx, %7
    mov %3, [ecx]
%endmacro
; the same with the frame's slots
%macro FRAME_TEXEL 3
    MASKED_TEXEL [esp + %1], [esp + %2], %3, [esp + L_VMASK], [esp + L_PITCH], [esp + L_UMASK], [esp + L_TEXTURE]
%endmacro

; the core's registers (asm/core816.inc) from the steps du (eax) and dv (edx) and the segment's
; start [esp + L_U0], [esp + L_V0]
%macro CORE_LOAD 0
    mov esi, eax
    shl esi, 16                         ; du fraction
    mov ebp, edx
    shl ebp, 16                         ; dv fraction
    shr eax, 16                         ; al: du whole
    shr edx, 16
    mov ah, dl                          ; ah: dv whole
    mov ebx, [esp + L_TEXTURE]
    mov bl, [esp + L_U0 + 2]            ; u whole
    mov bh, [esp + L_V0 + 2]            ; v whole
    mov edx, [esp + L_V0]
    shl edx, 16                         ; v fraction
    mov dx, ax                          ; dl: du whole, dh: dv whole
    mov eax, [esp + L_U0]
    shl eax, 16                         ; u fraction
%endmacro

; The doubled core's registers (asm/core816.inc) from the steps du (eax) and dv (edx) and the
; segment's start [esp + L_U0], [esp + L_V0]: the pointer at the start's wholes modulo the sides,
; a side further on each axis along which it falls, so that a travel of less than the side and 7
; texels either way stays in the copy (docs/bounds.md, "The subdivided fast mappers on the doubled
; copy"); ecx clobbered.
%macro DCORE_LOAD 0
    mov ebp, eax
    shl ebp, 16                         ; du fraction
    mov ebx, edx
    shl ebx, 16
    mov [esp + L_DVF], ebx              ; dv fraction
    mov ecx, edx
    sar ecx, 31
    and ecx, [esp + L_VNEG]             ; a falling v: a side further on
    mov esi, [esp + L_V0]
    shr esi, 16
    and esi, [esp + L_VMASK]
    add esi, ecx
    imul esi, [esp + L_PITCH]           ; the row
    mov ecx, eax
    sar ecx, 31
    and ecx, [esp + L_UNEG]
    add esi, ecx
    mov ebx, [esp + L_U0]
    shr ebx, 16
    and ebx, [esp + L_UMASK]
    add esi, ebx                        ; and the column
    add esi, [esp + L_TEXTURE]
    sar edx, 16
    imul edx, [esp + L_PITCH]
    sar eax, 16
    add edx, eax                        ; dv's whole rows and du's whole columns
    mov [esp + L_DSTEP0], edx
    add edx, [esp + L_PITCH]
    mov [esp + L_DSTEP], edx
    mov ebx, [esp + L_U0]
    shl ebx, 16                         ; u fraction
    mov edx, [esp + L_V0]
    shl edx, 16                         ; v fraction
%endmacro

; To %3 where the segment's travel along an axis could leave the copy: its ends' difference (the
; slots %1 less %2) not within the reach at slot %4 (the 16.16 reach r and 2 r after it:
; -r <= d < r); ebx clobbered.
%macro REACH 4
    mov ebx, [esp + %1]
    sub ebx, [esp + %2]
    add ebx, [esp + %4]
    cmp ebx, [esp + %4 + 4]
    jae %3
%endmacro

; The doubled core's pairs from the entry at [esp + L_ENTRY], then the odd last pixel where
; [esp + L_ODD] says so; then on at %1.
%macro DPAIRS_AND_ODD 1
    jmp [esp + L_ENTRY]
    DPAIR_BLOCKS
.odd_pixel:                             ; edi: just past the pairs
    cmp dword [esp + L_ODD], 0
    je %1
    mov al, [esi]
    mov [edi], al
%endmacro

; The doubled core down a column: blocks of eight, [esp + L_BLOCKS] of them, entered at .e0 to .e7.
%macro DSTRIDE_PIXEL 0
    mov al, [esi]
    DOUBLED_STEP L_DVF, L_DSTEP0
    mov [edi], al
    add edi, [esp + L_STRIDE]
%endmacro
%macro DSTRIDE_BLOCKS 0
.block:
.e0: DSTRIDE_PIXEL
.e1: DSTRIDE_PIXEL
.e2: DSTRIDE_PIXEL
.e3: DSTRIDE_PIXEL
.e4: DSTRIDE_PIXEL
.e5: DSTRIDE_PIXEL
.e6: DSTRIDE_PIXEL
.e7: DSTRIDE_PIXEL
    dec dword [esp + L_BLOCKS]
    jnz .block
%endmacro

; Columns: each pixel stored, then the destination moved on by the stride; blocks of eight
; entered at .e0 to .e7 (the pixel the first block starts at: nothing to move back), ecx of them.
%macro STRIDE_PIXEL 0
    PIXEL 0
    add edi, [esp + L_STRIDE]
%endmacro
%macro STRIDE_BLOCKS 0
.block:
.e0: STRIDE_PIXEL
.e1: STRIDE_PIXEL
.e2: STRIDE_PIXEL
.e3: STRIDE_PIXEL
.e4: STRIDE_PIXEL
.e5: STRIDE_PIXEL
.e6: STRIDE_PIXEL
.e7: STRIDE_PIXEL
    dec ecx
    jnz .block
%endmacro

; The computed entry into STRIDE_BLOCKS for ecx pixels (in; out: the blocks): the first block
; starts at pixel (-pixels) mod 8, [esp + L_ENTRY] takes that entry of the table %2; %1: scratch.
%macro PIXEL_ENTRY 2
    mov %1, ecx
    neg %1
    and %1, 7
    mov %1, [%2 + %1 * 4]
    mov [esp + L_ENTRY], %1
    add ecx, 7
    shr ecx, 3
%endmacro

; One span, rows (%1 = rows: stride 1, pairs) or columns (%1 = columns: the stride's); %2: the
; entry table; %3: tiled (the 8:16 core) or doubled (the doubled core, each segment's travel
; checked; where it could leave the copy the segment's pixels read it by masks, .masked). Full
; segments keep x (the next exact point's, in subpixels) on the x87 stack, one add of n * 256 a
; segment (exact: whole numbers below 2^53, as the twin's x0 + k * 256); their entry into the
; blocks is the same every time, found once a span. The last segment (at most n pixels, its exact
; point the span's last pixel) finds its own and divides.
%macro SUBDIV_SPAN 3
    LOOP_ENTER L_FRAME
    mov edx, LOOP_ARG(L_FRAME)
    mov eax, [edx + FSUB_count]
    test eax, eax
    jle .done
    mov [esp + L_ARGS], edx
    mov [esp + L_LEFT], eax
    dec eax
    mov [esp + L_LAST], eax
    FRAME_COPY edx, FSUB_dst, L_DST, FSUB_texture, L_TEXTURE
%ifidn %3, doubled
    DOUBLED_BLOCK edx, esp + L_TEXTURE, esp + L_PITCH, esp + L_UMASK, esp + L_VMASK
    REACHES L_UMASK, L_UNEG, L_UREACH
    REACHES L_VMASK, L_VNEG, L_VREACH
%endif
    mov ecx, [edx + FSUB_shift]
    mov [esp + L_SHIFT], ecx
    mov eax, [edx + FSUB_stride]
    mov [esp + L_STRIDE], eax
    mov ebx, 1
    shl ebx, cl
    mov [esp + L_N], ebx
    cmp [esp + L_LEFT], ebx
    jle .first_point                    ; one segment: none of a full segment's set-up
    mov dword [esp + L_ODD], 0          ; (a full segment's pixels are pairs)
    shl eax, cl
    mov [esp + L_SEG_BYTES], eax        ; n * stride
    shl ebx, 8
    mov [esp + L_D], ebx
    fild dword [esp + L_D]
    fstp qword [esp + L_SEG_X]          ; n * 256, exact
    mov ecx, [esp + L_N]
    xor edi, edi
%ifidn %1, rows
    shr ecx, 1                          ; a full segment's pairs
    PAIR_ENTRY edi, eax, %2
%else
    PIXEL_ENTRY eax, %2
%endif
    mov [esp + L_FULL_BACK], edi
    mov [esp + L_FULL_BLOCKS], ecx
    mov eax, [esp + L_ENTRY]
    mov [esp + L_FULL_ENTRY], eax
    mov ecx, edx
    fldz
    fadd qword [ecx + FSUB_x]           ; x at pixel 0 (0 + x0, as the twin's x0 + 0 * 256)
    POINT_AT L_U0, L_V0                 ; (qword stores, u's first: its high dword is then
                                        ; overwritten by v's low one, and v's high one lands in
                                        ; U1, written again before it is read)
    jmp .full_segment
.first_point:                           ; one segment: its first point, then the last
    mov ecx, edx
    fldz
    fadd qword [ecx + FSUB_x]
    POINT_AT L_U0, L_V0
    jmp .last_segment
.full_segment:                          ; more than n pixels left: n of them, to the exact point n on
    fadd qword [esp + L_SEG_X]
    mov ecx, [esp + L_ARGS]
    POINT
    mov ecx, [esp + L_SHIFT]
    mov eax, [esp + L_U1]
    sub eax, [esp + L_U0]
    sar eax, cl                         ; du
    mov edx, [esp + L_V1]
    sub edx, [esp + L_V0]
    sar edx, cl                         ; dv
%ifidn %3, doubled
    REACH L_U1, L_U0, .masked_full, L_UREACH
    REACH L_V1, L_V0, .masked_full, L_VREACH
    mov edi, [esp + L_DST]
    add edi, [esp + L_FULL_BACK]
    DCORE_LOAD
    mov ecx, [esp + L_FULL_BLOCKS]
    mov [esp + L_BLOCKS], ecx
%else
    mov edi, [esp + L_DST]
    add edi, [esp + L_FULL_BACK]
    mov ecx, [esp + L_FULL_BLOCKS]
    CORE_LOAD
%endif
    jmp [esp + L_FULL_ENTRY]
.last_segment:                          ; the pixels left, to the exact point at the last
    fstp st0                            ; (the full segments' x)
    mov eax, [esp + L_LEFT]
    dec eax
    jz .one_pixel
    mov [esp + L_D], eax
    mov ecx, [esp + L_ARGS]
    fild dword [esp + L_LAST]
    fmul qword [subpixel_one]
    fadd qword [ecx + FSUB_x]           ; x = x0 + last * 256
    POINT
    fstp st0
    cmp eax, 1                          ; (d: POINT leaves eax)
    je .two_pixels
    mov eax, [esp + L_U1]
    sub eax, [esp + L_U0]
    cdq
    idiv dword [esp + L_D]
    mov ebx, eax                        ; du
    mov eax, [esp + L_V1]
    sub eax, [esp + L_V0]
    cdq
    idiv dword [esp + L_D]
    mov edx, eax                        ; dv
    mov eax, ebx
%ifidn %3, doubled
    REACH L_U1, L_U0, .masked_last, L_UREACH
    REACH L_V1, L_V0, .masked_last, L_VREACH
%endif
    jmp .last_draw
.one_pixel:                             ; the texel at the segment's first point, stored (the core's
                                        ; first pixel, without its set-up: a last segment of one or
                                        ; two pixels after full ones; shorter spans: fast_subdiv_short)
%ifidn %3, doubled
    FRAME_TEXEL L_U0, L_V0, al
%else
    TEXEL_AT L_U0, L_V0, al, [esp + L_TEXTURE]
%endif
    mov edi, [esp + L_DST]
    mov [edi], al
    jmp .done                           ; (the last segment)
.two_pixels:                            ; the two exact points' texels: the core's second pixel is
                                        ; U0 + (U1 - U0) / 1, the second point itself
%ifidn %3, doubled
    FRAME_TEXEL L_U0, L_V0, al
    FRAME_TEXEL L_U1, L_V1, ah
%else
    TEXEL_AT L_U0, L_V0, al, [esp + L_TEXTURE]
    TEXEL_AT L_U1, L_V1, ah, [esp + L_TEXTURE]
%endif
    mov edi, [esp + L_DST]
%ifidn %1, rows
    mov [edi], ax
%else
    mov [edi], al
    add edi, [esp + L_STRIDE]
    mov [edi], ah
%endif
    jmp .done
%ifidn %3, doubled
.masked_full:                           ; eax: du, edx: dv; a full segment's pixels
    mov ecx, [esp + L_N]
    jmp .masked
.masked_last:                           ; and the last's
    mov ecx, [esp + L_LEFT]
.masked:                                ; ecx pixels from the segment's start by masks (the twin's)
    mov [esp + L_BLOCKS], ecx
    mov [esp + L_DU], eax
    mov [esp + L_DV], edx
    mov edi, [esp + L_DST]
    mov esi, [esp + L_U0]
    mov ebp, [esp + L_V0]
.masked_pixel:
    MASKED_TEXEL esi, ebp, al, [esp + L_VMASK], [esp + L_PITCH], [esp + L_UMASK], [esp + L_TEXTURE]
    mov [edi], al
    add edi, [esp + L_STRIDE]
    add esi, [esp + L_DU]
    add ebp, [esp + L_DV]
    dec dword [esp + L_BLOCKS]
    jnz .masked_pixel
    jmp .next
%endif
.last_draw:                             ; eax: du, edx: dv
    mov ecx, [esp + L_LEFT]
    mov edi, [esp + L_DST]
%ifidn %1, rows
    mov ebx, ecx
    and ebx, 1
    mov [esp + L_ODD], ebx
    shr ecx, 1                          ; pairs
    PAIR_ENTRY edi, ebx, %2             ; blocks, the first one partial
%ifidn %3, doubled
    mov [esp + L_BLOCKS], ecx
    DCORE_LOAD
    cmp dword [esp + L_BLOCKS], 0
    je .odd_pixel                       ; no pair: one pixel
    DPAIRS_AND_ODD .next
%else
    CORE_LOAD                           ; (leaves ecx and edi)
    test ecx, ecx
    jz .odd_pixel                       ; no pair: one pixel
    PAIRS_AND_ODD .next
%endif
%else
    PIXEL_ENTRY ebx, %2                 ; blocks, the first one partial
%ifidn %3, doubled
    mov [esp + L_BLOCKS], ecx
    DCORE_LOAD
    jmp [esp + L_ENTRY]
    DSTRIDE_BLOCKS
%else
    CORE_LOAD
    jmp [esp + L_ENTRY]
    STRIDE_BLOCKS
%endif
%endif
.next:
    mov eax, [esp + L_N]
    mov ecx, [esp + L_LEFT]
    sub ecx, eax
    jle .done                           ; that was the last segment
    mov edx, [esp + L_SEG_BYTES]
    add [esp + L_DST], edx
    mov [esp + L_LEFT], ecx
    mov edx, [esp + L_U1]
    mov [esp + L_U0], edx
    mov edx, [esp + L_V1]
    mov [esp + L_V0], edx
    cmp ecx, eax
    jg .full_segment
    jmp .last_segment
.done:
    LOOP_LEAVE L_FRAME
%endmacro

; The doubled copy of the block %1's source: its origin, pitch and sides less one into [%2] to [%5]
; (eax and ecx clobbered).
%macro DOUBLED_BLOCK 5
    mov ecx, [%1 + FSUB_source]
    mov eax, [ecx + FTEX_width]
    dec eax
    mov [%4], eax                       ; u mask
    lea eax, [eax * 2 + 2 + 2 * DOUBLED_LEAD]
    mov [%3], eax                       ; pitch: 2 W + 2 lead
    imul eax, DOUBLED_LEAD
    add eax, [ecx + FTEX_doubled]
    add eax, DOUBLED_LEAD
    mov [%2], eax                       ; origin: lead rows and lead columns in
    mov eax, [ecx + FTEX_height]
    dec eax
    mov [%5], eax                       ; v mask
%endmacro

; The doubled copy's side along an axis from its mask at frame slot %1: the side into slot %2, and
; the reach of a segment's travel, (side + 6) in 16.16, and twice that into %3 and %3 + 4 (REACH).
%macro REACHES 3
    mov eax, [esp + %1]
    inc eax
    mov [esp + %2], eax
    add eax, 6
    shl eax, 16
    mov [esp + %3], eax
    add eax, eax
    mov [esp + %3 + 4], eax
%endmacro

; Rows go on here; any other stride to the column loop (the same frame and argument).
; On a doubled copy (FSUB_texture null) to fast_subdiv_doubled_asm.
global fast_subdiv_loop_asm
fast_subdiv_loop_asm:
    mov edx, [esp + 4]
    cmp dword [edx + FSUB_texture], 0
    je fast_subdiv_doubled_asm
    mov eax, [edx + FSUB_count]
    dec eax
    cmp eax, 1
    jbe fast_subdiv_short               ; one or two pixels
    cmp dword [edx + FSUB_stride], 1
    jne fast_subdiv_column_asm
    SUBDIV_SPAN rows, pair_entries, tiled

fast_subdiv_column_asm:
    SUBDIV_SPAN columns, column_entries, tiled

; The same on a doubled copy: rows, columns (fast_subdiv_doubled_column) and short spans
; (fast_subdiv_short's, by masks); edx: the block.
fast_subdiv_doubled_asm:
    mov eax, [edx + FSUB_count]
    dec eax
    cmp eax, 1
    jbe fast_subdiv_short_doubled
    cmp dword [edx + FSUB_stride], 1
    jne fast_subdiv_doubled_column
    SUBDIV_SPAN rows, doubled_pair_entries, doubled

fast_subdiv_doubled_column:
    SUBDIV_SPAN columns, doubled_column_entries, doubled

; A span of one or two pixels (most of a mesh's: triangles of a dozen pixels), rows or columns:
; its exact points' texels (the second pixel's step is the second point less the first, so the
; core would read the second point's texel), with no saved register and no core, a frame of its
; points (and on a doubled copy its block's origin, pitch and masks, read by masks); edx: the block.
%macro SHORT_SPAN 1-2 32               ; %1: the texel read (a macro of u slot, v slot, register); %2: the frame
    sub esp, %2                         ; U0, V0, U1, V1 (qwords), and the doubled copy's block
%if %2 > 32
    DOUBLED_BLOCK edx, esp + S_ORIGIN, esp + S_PITCH, esp + S_UMASK, esp + S_VMASK
%endif
    fldz
    fadd qword [edx + FSUB_x]           ; x at pixel 0, as the twin's x0 + 0 * 256
    POINT_AT 0, 8, edx
    cmp dword [edx + FSUB_count], 1
    jne .two                            ; (two pixels)
    fstp st0
    %1 0, 8, al
    mov ecx, [edx + FSUB_dst]
    mov [ecx], al
    add esp, %2
    ret
.two:
    fadd qword [subpixel_one]           ; pixel 1: x0 + 256
    POINT_AT 16, 24, edx
    fstp st0
    %1 0, 8, al
    %1 16, 24, ah
    mov ecx, [edx + FSUB_dst]
    mov [ecx], al
    add ecx, [edx + FSUB_stride]
    mov [ecx], ah
    add esp, %2
    ret
%endmacro
; the tiled block's texel (TEXEL_AT), and the doubled copy's by masks (ebx is the caller's here:
; kept)
%macro TILED_SHORT_TEXEL 3
    TEXEL_AT %1, %2, %3
%endmacro
S_ORIGIN      equ 32                    ; the short doubled span's frame: the doubled copy's block
S_PITCH       equ 36
S_UMASK       equ 40
S_VMASK       equ 44
%macro DOUBLED_SHORT_TEXEL 3
    push ebx
    MASKED_TEXEL [esp + 4 + %1], [esp + 4 + %2], %3, [esp + 4 + S_VMASK], [esp + 4 + S_PITCH], [esp + 4 + S_UMASK], [esp + 4 + S_ORIGIN]
    pop ebx
%endmacro
fast_subdiv_short:
    SHORT_SPAN TILED_SHORT_TEXEL
fast_subdiv_short_doubled:
    SHORT_SPAN DOUBLED_SHORT_TEXEL, 48

section .rodata
align 4
    ENTRIES pair_entries, fast_subdiv_loop_asm, 8
    ENTRIES column_entries, fast_subdiv_column_asm, 8
    ENTRIES doubled_pair_entries, fast_subdiv_doubled_asm, 8
    ENTRIES doubled_column_entries, fast_subdiv_doubled_column, 8
