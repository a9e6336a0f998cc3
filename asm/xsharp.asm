; X-Sharp's Mode X inner loops (Abrash, Black Book ch. 57-58), in 32-bit flat code; twins of
; xsharp_row_loop and xsharp_column_loop in kernel/mappers/xsharp.cpp.

bits 32

%include "xsharp.inc"
%include "loop.inc"

SC_INDEX    equ 0x3C4
SC_DATA     equ 0x3C5
MAP_MASK    equ 2

section .text

; xsharp_row_loop_asm: listing 57.2's TexScanLoop (= listing 58.1): an OUT to the Map Mask before every
; pixel. The fractions live in memory, as 57.2's BP-relative locals did (a copy on our stack).
;   al:  plane mask, the plane bit in both nibbles (rol carries out of bit 7 when the plane wraps)
;   dx:  SC_DATA          esi: texel pointer (both integer parts)     edi: destination byte
;   ebp: pixels left      cx:  fraction scratch                        ebx: the args copy
global xsharp_row_loop_asm
xsharp_row_loop_asm:
    LOOP_ENTER 0
    mov esi, LOOP_ARG(0)
    sub esp, XROW_ARGS_SIZE
    mov edi, esp                        ; a copy of the block: the fractions change
    mov ecx, XROW_ARGS_SIZE / 4
    rep movsd
    mov ebx, esp
    mov dx, SC_INDEX
    mov al, MAP_MASK
    out dx, al                          ; the Sequencer index stays at the Map Mask
    inc dx                              ; SC_DATA
    mov edi, [ebx + XROW_dst]
    mov esi, [ebx + XROW_texel]
    mov ebp, [ebx + XROW_count]
    mov eax, [ebx + XROW_mask]
    test ebp, ebp
    jle .done
.pixel:
    out dx, al                          ; this pixel's plane
    mov ah, [esi]
    mov [edi], ah
    add esi, [ebx + XROW_x_base]        ; whole X step
    mov cx, [ebx + XROW_x_step]
    add [ebx + XROW_x_frac], cx         ; X fraction (16 bits)
    jnc .no_x_carry
    add esi, [ebx + XROW_x_carry]
.no_x_carry:
    add esi, [ebx + XROW_y_base]        ; whole Y step times the pitch
    mov cx, [ebx + XROW_y_step]
    add [ebx + XROW_y_frac], cx
    jnc .no_y_carry
    add esi, [ebx + XROW_y_carry]
.no_y_carry:
    rol al, 1                           ; next plane; the carry out of 88h -> 11h is the next byte
    adc edi, 0
    dec ebp
    jnz .pixel
.done:
    LOOP_LEAVE XROW_ARGS_SIZE

; xsharp_column_loop_asm: listing 58.4's loop as X-Sharp 22 shipped it: unrolled twice, the odd pixel
; entered half-way with the destination moved back a row, and a second loop (SBB) for X running
; backwards. The map mask is already set for the column.
;   edx: fractions (X in 31..16, Y >> 1 in 14..0, bit 15 the Y carry)   ebp: the packed steps
;   esi: texel pointer   eax: whole X + whole Y * pitch (negated for the backwards loop)
;   ecx: +-pitch (the Y carry)   edi: destination   bl: texel   [esp]: pixel pairs left
%macro PIXEL 3                          ; %1 row offset, %2 adc|sbb, %3 label
    mov bl, [esi]
    add edx, ebp                        ; both fractions at once; CF = the X carry
    %2 esi, eax                         ; whole advance plus (adc) or minus (sbb) the X carry
    mov [edi + %1], bl
    test dh, 0x80                       ; the Y carry
    jz %3
    add esi, ecx
    and dh, 0x7F
%3:
%endmacro

global xsharp_column_loop_asm
xsharp_column_loop_asm:
    LOOP_ENTER 4
    mov ebx, LOOP_ARG(4)
    mov eax, [ebx + XCOL_count]
    test eax, eax
    jle .done
    inc eax
    shr eax, 1                          ; pixel pairs, rounded up
    mov [esp], eax
    mov edi, [ebx + XCOL_dst]
    mov esi, [ebx + XCOL_texel]
    mov edx, [ebx + XCOL_fractions]
    mov ebp, [ebx + XCOL_steps]
    mov eax, [ebx + XCOL_base]
    mov ecx, [ebx + XCOL_row]
    test byte [ebx + XCOL_count], 1     ; odd: enter at the second pixel of a pair, a row early
    jnz .odd
    cmp dword [ebx + XCOL_backwards], 0
    jne .backwards
    jmp .forward
.odd:
    sub edi, XSHARP_SCANWIDTH
    cmp dword [ebx + XCOL_backwards], 0
    jne .backwards_odd
    jmp .forward_odd

.forward:
    PIXEL 0, adc, .f0
.forward_odd:
    PIXEL XSHARP_SCANWIDTH, adc, .f1
    add edi, 2 * XSHARP_SCANWIDTH
    dec dword [esp]
    jnz .forward
    jmp .done

.backwards:
    neg eax                             ; sbb esi, -base: esi + base - carry
    jmp .backwards_top
.backwards_odd:
    neg eax
    jmp .backwards_second
.backwards_top:
    PIXEL 0, sbb, .b0
.backwards_second:
    PIXEL XSHARP_SCANWIDTH, sbb, .b1
    add edi, 2 * XSHARP_SCANWIDTH
    dec dword [esp]
    jnz .backwards_top

.done:
    LOOP_LEAVE 4
